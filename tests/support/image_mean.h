#pragma once

#include "core/film/film_buffer.h"

namespace caustica::test {

// A film's mean per channel over its pixels, with the standard errors its
// per-pixel variances give, and how many pixel values were not finite.
struct ImageMean {
  double mean[3], standard_error[3];
  int non_finite = 0;
};
ImageMean image_mean(const FilmBuffer& film);

}  // namespace caustica::test

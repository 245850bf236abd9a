#include "tests/support/image_mean.h"

#include <cmath>

namespace caustica::test {

ImageMean image_mean(const FilmBuffer& film) {
  const auto img = film.resolve();
  const auto var = film.variance();
  const double pixels = double(img.size() / 3);
  ImageMean m{};
  for (int c = 0; c < 3; ++c) {
    double sum = 0, var_sum = 0;
    for (size_t i = size_t(c); i < img.size(); i += 3) {
      m.non_finite += !std::isfinite(img[i]);
      sum += img[i];
      var_sum += var[i];
    }
    m.mean[c] = sum / pixels;
    m.standard_error[c] = std::sqrt(var_sum) / pixels;
  }
  return m;
}

}  // namespace caustica::test

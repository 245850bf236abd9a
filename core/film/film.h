#pragma once

#include <memory>
#include <string>

#include "core/film/reconstruction_filter.h"
#include "core/registry/plugin.h"

namespace caustica {

// The film's settings as the scene gives them (hdrfilm); pixels accumulate
// in a FilmBuffer made for each render.
class Film : public Plugin {
 public:
  Film(int width, int height, std::shared_ptr<ReconstructionFilter> filter, bool half_float)
      : width_(width), height_(height), filter_(std::move(filter)), half_float_(half_float) {}

  int width() const { return width_; }
  int height() const { return height_; }
  const ReconstructionFilter& filter() const { return *filter_; }
  bool half_float() const { return half_float_; }

 private:
  int width_, height_;
  std::shared_ptr<ReconstructionFilter> filter_;
  bool half_float_;
};

}  // namespace caustica

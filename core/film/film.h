#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/film/reconstruction_filter.h"
#include "core/math/vec.h"
#include "core/registry/plugin.h"

namespace caustica {

// The file an hdrfilm asks to be written (Mitsuba's file_format).
enum class FileFormat { OpenExr, Rgbe, Pfm };

// What the image's colour channels hold (Mitsuba's pixel_format): RGB
// always, with luminance (Y) or CIE XYZ beside it, and optionally alpha.
enum class PixelFormat { Rgb, Luminance, Xyz };

// How an ldrfilm develops its 8-bit image (Mitsuba 0.x's settings):
// tonemap "gamma" (exposure only) or "reinhard" (key, burn), then a power
// gamma, or sRGB's curve for -1.
struct LdrDevelopment {
  std::string tonemap = "gamma";
  float gamma = -1, exposure = 0, key = 0.18f, burn = 0;
  bool jpeg = false;
};

// How the film is written, as the scene asks.
struct FilmOutput {
  FileFormat file = FileFormat::OpenExr;
  PixelFormat pixels = PixelFormat::Rgb;
  bool alpha = false;
  bool half_float = true;
  std::optional<LdrDevelopment> ldr;  // for an ldrfilm
};

// The pixels a film has and renders.
struct FilmGeometry {
  Vec2i full, crop_offset, crop_size;
  std::shared_ptr<ReconstructionFilter> filter;
};

// The film's settings as the scene gives them (hdrfilm); pixels accumulate
// in a FilmBuffer made for each render. A crop window renders part of the
// film: width() and height() are the window's, and the sensor maps the
// window's pixels into the whole film.
class Film : public Plugin {
 public:
  Film(FilmGeometry geometry, FilmOutput output)
      : full_size_(geometry.full),
        crop_offset_(geometry.crop_offset),
        crop_size_(geometry.crop_size),
        filter_(std::move(geometry.filter)),
        output_(std::move(output)) {}

  int width() const { return crop_size_.x; }
  int height() const { return crop_size_.y; }
  Vec2i full_size() const { return full_size_; }
  Vec2i crop_offset() const { return crop_offset_; }
  const ReconstructionFilter& filter() const { return *filter_; }
  const FilmOutput& output() const { return output_; }
  bool half_float() const { return output_.half_float; }

 private:
  Vec2i full_size_, crop_offset_, crop_size_;
  std::shared_ptr<ReconstructionFilter> filter_;
  FilmOutput output_;
};

}  // namespace caustica

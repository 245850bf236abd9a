#pragma once

#include <memory>
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

// How the film is written, as the scene asks.
struct FilmOutput {
  FileFormat file = FileFormat::OpenExr;
  PixelFormat pixels = PixelFormat::Rgb;
  bool alpha = false;
  bool half_float = true;
};

// The film's settings as the scene gives them (hdrfilm); pixels accumulate
// in a FilmBuffer made for each render. A crop window renders part of the
// film: width() and height() are the window's, and the sensor maps the
// window's pixels into the whole film.
class Film : public Plugin {
 public:
  Film(Vec2i full_size, Vec2i crop_offset, Vec2i crop_size, std::shared_ptr<ReconstructionFilter> filter,
       FilmOutput output)
      : full_size_(full_size),
        crop_offset_(crop_offset),
        crop_size_(crop_size),
        filter_(std::move(filter)),
        output_(output) {}

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

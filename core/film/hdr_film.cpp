// hdrfilm: a linear, high-dynamic-range film, written as OpenEXR (or, as
// file_format asks, Radiance RGBE or PFM).
//
// A nested rfilter (box, tent or gaussian) reconstructs the pixels from the
// samples; without one it is a gaussian with its default parameters. A crop
// window renders only part of the film, seen as the whole film would see it.
//
//   <film type="hdrfilm">
//       <integer name="width" value="512"/>
//       <integer name="height" value="512"/>
//       <rfilter type="tent"/>
//   </film>

#include <algorithm>
#include <tuple>

#include "core/film/film.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {

std::shared_ptr<ReconstructionFilter> filter_or_default(const Properties& props) {
  if (auto f = props.child<ReconstructionFilter>("rfilter")) return f;
  return Registry::instance().create_default<ReconstructionFilter>("rfilter", "gaussian", props.where());
}

int in_range(const Properties& props, const char* name, int64_t value, int64_t lo, int64_t hi) {
  if (value < lo || value > hi)
    throw props.error(name, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return int(value);
}

Vec2i read_size(const Properties& props) {
  return {in_range(props, "width", props.get_int("width"), 1, 1 << 16),
          in_range(props, "height", props.get_int("height"), 1, 1 << 16)};
}

FilmOutput read_output(const Properties& props) {
  FilmOutput out;
  const std::string file = props.get_string("file_format");
  if (file == "openexr" || file == "exr")
    out.file = FileFormat::OpenExr;
  else if (file == "rgbe")
    out.file = FileFormat::Rgbe;
  else if (file == "pfm")
    out.file = FileFormat::Pfm;
  else
    throw props.error("file_format", "must be openexr, rgbe or pfm, not '" + file + "'");

  static const std::tuple<const char*, PixelFormat, bool> kPixelFormats[] = {
      {"rgb", PixelFormat::Rgb, false},
      {"rgba", PixelFormat::Rgb, true},
      {"luminance", PixelFormat::Luminance, false},
      {"luminance_alpha", PixelFormat::Luminance, true},
      {"xyz", PixelFormat::Xyz, false},
      {"xyza", PixelFormat::Xyz, true}};
  const std::string pixels = props.get_string("pixel_format");
  const auto it = std::find_if(std::begin(kPixelFormats), std::end(kPixelFormats),
                               [&](const auto& f) { return pixels == std::get<0>(f); });
  if (it == std::end(kPixelFormats))
    throw props.error("pixel_format",
                      "must be rgb, rgba, luminance, luminance_alpha, xyz or xyza, not '" + pixels + "'");
  out.pixels = std::get<1>(*it);
  out.alpha = std::get<2>(*it);

  const std::string component = props.get_string("component_format");
  if (component != "float16" && component != "float32" && component != "uint32")
    throw props.error("component_format", "must be float16, float32 or uint32, not '" + component + "'");
  out.half_float = component == "float16";
  if (component == "uint32")
    props.warn("component_format", "uint32 is written as float32: integers would truncate the radiance");
  if (out.file != FileFormat::OpenExr && props.has("component_format") && component != "float32")
    props.warn("component_format", "RGBE and PFM files hold their own formats; this has no effect");
  return out;
}

class HdrFilm final : public Film {
  // 8192 x 8192; the accumulation buffers take about 100 bytes a pixel.
  static constexpr int64_t kMaxPixels = int64_t(1) << 26;

 public:
  explicit HdrFilm(const Properties& props)
      : Film(read_size(props), read_crop_offset(props), read_crop_size(props), filter_or_default(props),
             read_output(props)) {
    if (int64_t(width()) * height() > kMaxPixels)
      throw props.error(full_size() == Vec2i{width(), height()} ? "height" : "crop_height",
                        std::string("width x height") +
                            (full_size() == Vec2i{width(), height()} ? "" : " of the crop window") +
                            " must be at most " + std::to_string(kMaxPixels) + " pixels");
    for (const char* name : {"sample_border", "high_quality_edges"})
      if (props.get_bool(name))
        props.warn(name,
                   "has no effect: every pixel is already filtered over the filter's whole support, at the "
                   "film's borders too");
    for (const char* name : {"banner", "attach_log"})
      if (props.has(name)) props.warn(name, "is ignored: caustica writes neither a banner nor a log into images");
  }

 private:
  static Vec2i read_crop_offset(const Properties& props) {
    const Vec2i full = read_size(props);
    return {in_range(props, "crop_offset_x", props.get_int("crop_offset_x"), 0, full.x - 1),
            in_range(props, "crop_offset_y", props.get_int("crop_offset_y"), 0, full.y - 1)};
  }
  static Vec2i read_crop_size(const Properties& props) {
    const Vec2i full = read_size(props), offset = read_crop_offset(props);
    return {in_range(props, "crop_width", props.get_int_or("crop_width", full.x - offset.x), 1, full.x - offset.x),
            in_range(props, "crop_height", props.get_int_or("crop_height", full.y - offset.y), 1, full.y - offset.y)};
  }
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    HdrFilm, "film", "hdrfilm",
    {{"width", ParamType::Integer, "768", "width in pixels"},
     {"height", ParamType::Integer, "576", "height in pixels"},
     {"file_format", ParamType::String, "openexr", "openexr (or exr), rgbe (.hdr) or pfm"},
     {"pixel_format", ParamType::String, "rgb",
      "rgb, luminance or xyz, each with an alpha channel as rgba, luminance_alpha or xyza; an EXR keeps RGB "
      "and adds Y or X, Y, Z beside it"},
     {"component_format", ParamType::String, "float16", "float16 or float32 (uint32 is written as float32)"},
     {"crop_offset_x", ParamType::Integer, "0", "left column of the crop window"},
     {"crop_offset_y", ParamType::Integer, "0", "top row of the crop window"},
     {"crop_width", ParamType::Integer, std::nullopt, "crop window width (default: the rest of the film)"},
     {"crop_height", ParamType::Integer, std::nullopt, "crop window height (default: the rest of the film)"},
     {"sample_border", ParamType::Boolean, "false", "accepted; borders are always filtered completely"},
     {"high_quality_edges", ParamType::Boolean, "false", "Mitsuba 0.x's sample_border; accepted likewise"},
     {"banner", ParamType::Boolean, "false", "accepted and ignored"},
     {"attach_log", ParamType::Boolean, "false", "accepted and ignored"}},
    {"rfilter"});

}  // namespace caustica

#include "core/film/film_settings.h"

#include <algorithm>
#include <tuple>

#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// 8192 x 8192; the accumulation buffers take about 100 bytes a pixel.
constexpr int64_t kMaxPixels = int64_t(1) << 26;

int in_range(const Properties& props, const char* name, int64_t value, int64_t lo, int64_t hi) {
  if (value < lo || value > hi)
    throw props.error(name, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return int(value);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

FilmGeometry read_film_geometry(const Properties& props) {
  FilmGeometry g;
  g.full = {in_range(props, "width", props.get_int("width"), 1, 1 << 16),
            in_range(props, "height", props.get_int("height"), 1, 1 << 16)};
  g.crop_offset = {in_range(props, "crop_offset_x", props.get_int("crop_offset_x"), 0, g.full.x - 1),
                   in_range(props, "crop_offset_y", props.get_int("crop_offset_y"), 0, g.full.y - 1)};
  const Vec2i rest{g.full.x - g.crop_offset.x, g.full.y - g.crop_offset.y};
  g.crop_size = {in_range(props, "crop_width", props.get_int_or("crop_width", rest.x), 1, rest.x),
                 in_range(props, "crop_height", props.get_int_or("crop_height", rest.y), 1, rest.y)};
  const bool cropped = !(g.crop_size == g.full);
  if (int64_t(g.crop_size.x) * g.crop_size.y > kMaxPixels)
    throw props.error(cropped ? "crop_height" : "height",
                      std::string("width x height") + (cropped ? " of the crop window" : "") + " must be at most " +
                          std::to_string(kMaxPixels) + " pixels");
  g.filter = props.child<ReconstructionFilter>("rfilter");
  if (!g.filter)
    g.filter = Registry::instance().create_default<ReconstructionFilter>("rfilter", "gaussian", props.where());
  for (const char* name : {"sample_border", "high_quality_edges"})
    if (props.get_bool(name))
      props.warn(name,
                 "has no effect: every pixel is already filtered over the filter's whole support, at the "
                 "film's borders too");
  for (const char* name : {"banner", "attach_log"})
    if (props.has(name)) props.warn(name, "is ignored: caustica writes neither a banner nor a log into images");
  return g;
}

void read_pixel_format(const Properties& props, FilmOutput& out, const std::vector<std::string>& accepted) {
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
  if (it == std::end(kPixelFormats) || std::find(accepted.begin(), accepted.end(), pixels) == accepted.end()) {
    std::string list;
    for (size_t i = 0; i < accepted.size(); ++i)
      list += (i == 0 ? "" : i + 1 == accepted.size() ? " or " : ", ") + accepted[i];
    throw props.error("pixel_format", "must be " + list + ", not '" + pixels + "'");
  }
  out.pixels = std::get<1>(*it);
  out.alpha = std::get<2>(*it);
}

std::vector<ParamSpec> film_geometry_params() {
  return {{"width", ParamType::Integer, "768", "width in pixels"},
          {"height", ParamType::Integer, "576", "height in pixels"},
          {"crop_offset_x", ParamType::Integer, "0", "left column of the crop window"},
          {"crop_offset_y", ParamType::Integer, "0", "top row of the crop window"},
          {"crop_width", ParamType::Integer, std::nullopt, "crop window width (default: the rest of the film)"},
          {"crop_height", ParamType::Integer, std::nullopt, "crop window height (default: the rest of the film)"},
          {"sample_border", ParamType::Boolean, "false", "accepted; borders are always filtered completely"},
          {"high_quality_edges", ParamType::Boolean, "false", "Mitsuba 0.x's sample_border; accepted likewise"},
          {"banner", ParamType::Boolean, "false", "accepted and ignored"},
          {"attach_log", ParamType::Boolean, "false", "accepted and ignored"}};
}

}  // namespace caustica

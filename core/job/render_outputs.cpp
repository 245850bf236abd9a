#include "core/job/render_outputs.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include "core/camera/pixel_angle.h"
#include "core/version.h"

namespace caustica {

RenderLayers::RenderLayers(const FilmBuffer& film, const FilmBuffer* aovs, bool variance_known, bool raw_sums,
                           PixelFormat format)
    : RenderLayers(film, aovs ? aovs->channels() : std::vector<std::string>{},
                   aovs ? AovSource([aovs](int, int) {
                     return AovRows{aovs, 0};
                   })
                        : AovSource(),
                   false, variance_known, raw_sums, format) {}

RenderLayers::RenderLayers(const FilmBuffer& film, const FirstHitLayers* layers, bool variance_known, bool raw_sums,
                           PixelFormat format)
    : RenderLayers(
          film, layers ? layers->channels() : std::vector<std::string>{},
          layers ? AovSource([layers, band = std::make_shared<std::optional<FilmBuffer>>()](int y_begin, int y_end) {
            band->reset();  // before the next band is made, not beside it
            band->emplace(layers->evaluate(y_begin, y_end));
            return AovRows{&**band, size_t(y_begin) * size_t((*band)->width())};
          })
                 : AovSource(),
          true, variance_known, raw_sums, format) {}

RenderLayers::RenderLayers(const FilmBuffer& film, std::vector<std::string> aov_channels, AovSource aovs,
                           bool evaluated, bool variance_known, bool raw_sums, PixelFormat format)
    : aov_source_(std::move(aovs)), aovs_evaluated_(evaluated) {
  // Each layer writes its values for one pixel straight into the row.
  std::vector<std::string> names;
  const auto add = [&](const std::vector<std::string>& channels, std::function<void(size_t, float*)> fill,
                       bool from_aovs = false) {
    names.insert(names.end(), channels.begin(), channels.end());
    layers_.push_back({channels.size(), std::move(fill), from_aovs && evaluated});
    if (from_aovs && evaluated) rows_.float_only.insert(rows_.float_only.end(), channels.begin(), channels.end());
  };
  add(film.channels(), [&film](size_t p, float* out) { film.resolve_pixel(p, out); });
  if (aov_source_) {
    add(
        aov_channels, [this](size_t p, float* out) { aov_rows_.film->resolve_pixel(p - aov_rows_.first_pixel, out); },
        true);
    if (variance_known)
      add({"variance.R", "variance.G", "variance.B"}, [&film](size_t p, float* out) { film.variance_pixel(p, out); });
    add({"samples.Y"}, [&film](size_t p, float* out) {
      *out = float(film.sample_count({int(p % film.width()), int(p / film.width())}));
    });
  }
  if (raw_sums) {
    add(film.raw_channels("raw."), [&film](size_t p, float* out) { film.export_raw_pixel(p, out); });
    if (aov_source_) {
      // The raw sums' names need only the channels: a film of one pixel tells them.
      const FilmBuffer shape(1, 1, aov_channels, FilmBuffer::Moments::None);
      add(
          shape.raw_channels("raw.aov."),
          [this](size_t p, float* out) { aov_rows_.film->export_raw_pixel(p - aov_rows_.first_pixel, out); }, true);
    }
  }
  const auto at = [&](const char* name) { return int(std::find(names.begin(), names.end(), name) - names.begin()); };
  const int r = at("R"), g = at("G"), b = at("B");
  if (format != PixelFormat::Rgb && b < int(names.size())) {
    // Rows of the Rec. 709 (D65) to CIE XYZ matrix; the middle one is luminance.
    static const float kToXyz[3][3] = {{0.4124564f, 0.3575761f, 0.1804375f},
                                       {0.2126729f, 0.7151522f, 0.0721750f},
                                       {0.0193339f, 0.1191920f, 0.9503041f}};
    const int first = format == PixelFormat::Luminance ? 1 : 0, last = format == PixelFormat::Luminance ? 2 : 3;
    std::vector<std::string> xyz;
    for (int row = first; row < last; ++row) xyz.push_back(std::string(1, "XYZ"[row]));
    // The layer is filled after the others: its pixel's R, G, B lie behind it.
    const ptrdiff_t back = ptrdiff_t(names.size());
    add(xyz, [=](size_t, float* out) {
      const float* pixel = out - back;
      for (int row = first; row < last; ++row)
        out[row - first] = kToXyz[row][0] * pixel[r] + kToXyz[row][1] * pixel[g] + kToXyz[row][2] * pixel[b];
    });
  }
  rows_.width = film.width();
  rows_.height = film.height();
  rows_.channels = std::move(names);
  rows_.fill = [this](int y_begin, int y_end, float* out) { fill(y_begin, y_end, out, true); };
}

void RenderLayers::fill(int y_begin, int y_end, float* out, bool with_evaluated) const {
  const bool aovs = aov_source_ && (with_evaluated || !aovs_evaluated_);
  if (aovs) aov_rows_ = aov_source_(y_begin, y_end);
  const size_t width = size_t(rows_.width);
  for (size_t p = size_t(y_begin) * width; p < size_t(y_end) * width; ++p)
    for (const Layer& layer : layers_) {
      if (layer.evaluated && !with_evaluated)
        std::fill_n(out, layer.channels, 0.0f);
      else
        layer.fill(p, out);
      out += layer.channels;
    }
}

ExtremeValues RenderLayers::extreme_values() const {
  ImageRows scan = rows_;
  scan.fill = [this](int y_begin, int y_end, float* out) { fill(y_begin, y_end, out, false); };
  return count_extreme_values(scan);
}

Image RenderLayers::image() const {
  Image image{rows_.width, rows_.height, rows_.channels, {}};
  image.pixels.resize(size_t(image.width) * image.height * image.channels.size());
  rows_.fill(0, image.height, image.pixels.data());
  return image;
}

Image render_layers(const FilmBuffer& film, const FilmBuffer* aovs, bool variance_known, bool raw_sums) {
  return RenderLayers(film, aovs, variance_known, raw_sums).image();
}

void add_raw_channel_lists(const FilmBuffer& film, const std::vector<std::string>& aov_channels,
                           std::map<std::string, std::string>& metadata) {
  const auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
    return text;
  };
  metadata["caustica:raw_channels"] = list(film.channels());
  if (!aov_channels.empty()) metadata["caustica:raw_aov_channels"] = list(aov_channels);
}

std::map<std::string, std::string> render_metadata(const RenderJob& job, const RenderResult& result,
                                                   const std::string& scene_name, bool raw_sums) {
  const RenderStats& stats = result.stats;
  std::map<std::string, std::string> metadata = {{"caustica:scene", scene_name},
                                                 {"caustica:plan", job.plan()},
                                                 {"caustica:integrator", job.integrator().describe()},
                                                 {"caustica:first_sample", std::to_string(job.settings().first_sample)},
                                                 {"caustica:spp", std::to_string(stats.spp)},
                                                 {"caustica:seconds", std::to_string(stats.seconds)},
                                                 {"caustica:samples", std::to_string(stats.samples)},
                                                 {"caustica:rays", std::to_string(stats.rays)},
                                                 {"caustica:seed", std::to_string(job.settings().seed)},
                                                 {"caustica:interrupted", stats.interrupted ? "true" : "false"},
                                                 {"caustica:version", kVersion}};
  const double pixel_angle = degrees_per_pixel(job.scene()->sensor());
  if (pixel_angle > 0) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", pixel_angle);
    metadata["caustica:degrees_per_pixel"] = text;
  }
  if (!stats.summary.empty()) metadata["caustica:run"] = stats.summary;
  if (stats.ranks > 1) metadata["caustica:ranks"] = std::to_string(stats.ranks);
  if (!stats.ranges.empty()) metadata["caustica:ranges"] = stats.ranges;
  if (raw_sums) {
    const std::optional<FirstHitLayers> layers = job.first_hit_layers(result);
    add_raw_channel_lists(result.film, layers ? layers->channels() : std::vector<std::string>{}, metadata);
  }
  return metadata;
}

}  // namespace caustica

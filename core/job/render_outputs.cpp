#include "core/job/render_outputs.h"

#include <functional>

#include "core/version.h"

namespace caustica {

Image render_layers(const FilmBuffer& film, const FilmBuffer* aovs, bool variance_known, bool raw_sums) {
  // Each layer writes its values for one pixel straight into the image:
  // no layer is held whole beside it.
  struct Layer {
    std::vector<std::string> names;
    std::function<void(size_t pixel, float* out)> fill;
  };
  std::vector<Layer> layers;
  layers.push_back({film.channels(), [&](size_t p, float* out) { film.resolve_pixel(p, out); }});
  if (aovs) {
    layers.push_back({aovs->channels(), [&](size_t p, float* out) { aovs->resolve_pixel(p, out); }});
    if (variance_known)
      layers.push_back({{"variance.R", "variance.G", "variance.B"},
                        [&](size_t p, float* out) { film.variance_pixel(p, out); }});
    layers.push_back({{"samples.Y"}, [&](size_t p, float* out) {
                        *out = float(film.sample_count({int(p % film.width()), int(p / film.width())}));
                      }});
  }
  if (raw_sums) {
    layers.push_back({film.raw_channels("raw."), [&](size_t p, float* out) { film.export_raw_pixel(p, out); }});
    if (aovs)
      layers.push_back({aovs->raw_channels("raw.aov."), [&](size_t p, float* out) { aovs->export_raw_pixel(p, out); }});
  }
  Image image{film.width(), film.height(), {}, {}};
  for (const Layer& layer : layers) image.channels.insert(image.channels.end(), layer.names.begin(), layer.names.end());
  const size_t total = image.channels.size(), pixels = size_t(film.width()) * film.height();
  image.pixels.resize(pixels * total);
  for (size_t p = 0; p < pixels; ++p) {
    float* out = &image.pixels[p * total];
    for (const Layer& layer : layers) {
      layer.fill(p, out);
      out += layer.names.size();
    }
  }
  return image;
}

void add_pixel_format_channels(Image& image, PixelFormat format) {
  if (format == PixelFormat::Rgb) return;
  // Rows of the Rec. 709 (D65) to CIE XYZ matrix; the middle one is luminance.
  static const float kToXyz[3][3] = {
      {0.4124564f, 0.3575761f, 0.1804375f}, {0.2126729f, 0.7151522f, 0.0721750f}, {0.0193339f, 0.1191920f, 0.9503041f}};
  const int rows_begin = format == PixelFormat::Luminance ? 1 : 0, rows_end = format == PixelFormat::Luminance ? 2 : 3;
  const int r = image.channel_index("R"), g = image.channel_index("G"), b = image.channel_index("B");
  const size_t old_count = image.channels.size(), added = size_t(rows_end - rows_begin);
  const size_t pixels = size_t(image.width) * image.height;
  std::vector<float> out(pixels * (old_count + added));
  for (size_t p = 0; p < pixels; ++p) {
    const float* in = &image.pixels[p * old_count];
    float* o = &out[p * (old_count + added)];
    std::copy_n(in, old_count, o);
    for (int row = rows_begin; row < rows_end; ++row)
      o[old_count + size_t(row - rows_begin)] =
          kToXyz[row][0] * in[r] + kToXyz[row][1] * in[g] + kToXyz[row][2] * in[b];
  }
  for (int row = rows_begin; row < rows_end; ++row) image.channels.push_back(std::string(1, "XYZ"[row]));
  image.pixels = std::move(out);
}

void add_raw_channel_lists(const FilmBuffer& film, const FilmBuffer* aovs,
                           std::map<std::string, std::string>& metadata) {
  const auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
    return text;
  };
  metadata["caustica:raw_channels"] = list(film.channels());
  if (aovs) metadata["caustica:raw_aov_channels"] = list(aovs->channels());
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
  if (!stats.summary.empty()) metadata["caustica:run"] = stats.summary;
  if (raw_sums) add_raw_channel_lists(result.film, result.aovs ? &*result.aovs : nullptr, metadata);
  return metadata;
}

}  // namespace caustica

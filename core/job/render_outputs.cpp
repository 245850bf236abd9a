#include "core/job/render_outputs.h"

#include "core/version.h"

namespace caustica {

Image render_layers(const FilmBuffer& film, const FilmBuffer* aovs, bool variance_known, bool raw_sums) {
  const size_t pixels = size_t(film.width()) * film.height();
  std::vector<std::pair<std::vector<std::string>, std::vector<float>>> blocks;
  blocks.emplace_back(film.channels(), film.resolve());
  if (aovs) {
    blocks.emplace_back(aovs->channels(), aovs->resolve());
    if (variance_known)
      blocks.emplace_back(std::vector<std::string>{"variance.R", "variance.G", "variance.B"}, film.variance());
    std::vector<float> counts(pixels);
    for (size_t p = 0; p < pixels; ++p)
      counts[p] = float(film.sample_count({int(p % film.width()), int(p / film.width())}));
    blocks.emplace_back(std::vector<std::string>{"samples.Y"}, std::move(counts));
  }
  if (raw_sums) {
    blocks.emplace_back(film.raw_channels("raw."), film.export_raw());
    if (aovs) blocks.emplace_back(aovs->raw_channels("raw.aov."), aovs->export_raw());
  }
  Image image{film.width(), film.height(), {}, {}};
  for (const auto& [names, values] : blocks) image.channels.insert(image.channels.end(), names.begin(), names.end());
  const size_t total = image.channels.size();
  image.pixels.resize(pixels * total);
  size_t offset = 0;
  for (const auto& [names, values] : blocks) {
    const size_t n = names.size();
    for (size_t p = 0; p < pixels; ++p) std::copy_n(&values[p * n], n, &image.pixels[p * total + offset]);
    offset += n;
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

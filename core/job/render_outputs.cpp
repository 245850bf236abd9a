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

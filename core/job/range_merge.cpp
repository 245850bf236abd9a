#include "core/job/range_merge.h"

#include <algorithm>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/job/render_outputs.h"

namespace caustica {

namespace {

std::invalid_argument part_error(const RenderFile& part, const std::string& problem) {
  return std::invalid_argument("'" + part.path + "' " + problem);
}

const char* const kFilm = "raw.";
const char* const kAovs = "raw.aov.";

// The channels of the film whose raw sums start with `prefix`, in the
// film's order (an EXR keeps its channels in an order of its own), as
// render_metadata lists them.
std::vector<std::string> film_channels(const RenderFile& render, const std::string& key) {
  std::vector<std::string> names;
  std::istringstream list(metadata_value(render, key));
  for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  return names;
}

// Adds the part's raw sums under `prefix` to `film`, found by name (an EXR
// keeps its channels in an order of its own).
void add_part(const RenderFile& part, const std::string& prefix, uint64_t splat_paths, FilmBuffer& film) {
  const Image& image = part.image;
  const bool splats = image.channel_index(prefix + "splat." + film.channels().front() + ".0") >= 0;
  FilmBuffer shape(1, 1, film.channels());
  if (splats) shape.enable_splats();
  const std::vector<std::string> names = shape.raw_channels(prefix);
  std::vector<size_t> from;
  for (const std::string& name : names) {
    const int c = image.channel_index(name);
    if (c < 0) throw part_error(part, "lacks the raw sum " + name);
    from.push_back(size_t(c));
  }
  const size_t pixels = size_t(image.width) * image.height, nc = image.channels.size(), n = names.size();
  std::vector<float> sums(pixels * n);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t k = 0; k < n; ++k) sums[p * n + k] = image.pixels[p * nc + from[k]];
  film.add_raw(sums, n, 0, splats ? splat_paths : 0);
}

}  // namespace

bool has_raw_sums(const RenderFile& render) {
  return !film_channels(render, "caustica:raw_channels").empty() && render.image.channel_index("raw.count") >= 0;
}

RenderFile without_raw_sums(RenderFile render) {
  Image& image = render.image;
  const size_t nc = image.channels.size(), pixels = size_t(image.width) * image.height;
  std::vector<size_t> keep;
  for (size_t c = 0; c < nc; ++c)
    if (image.channels[c].rfind(kFilm, 0) != 0) keep.push_back(c);
  Image kept{image.width, image.height, {}, std::vector<float>(pixels * keep.size())};
  for (size_t c : keep) kept.channels.push_back(image.channels[c]);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t k = 0; k < keep.size(); ++k) kept.pixels[p * keep.size() + k] = image.pixels[p * nc + keep[k]];
  image = std::move(kept);
  render.metadata.erase("caustica:raw_channels");
  render.metadata.erase("caustica:raw_aov_channels");
  return render;
}

RenderFile merge_sample_ranges(const std::vector<RenderFile>& input) {
  if (input.empty()) throw std::invalid_argument("nothing to merge");
  std::vector<const RenderFile*> parts;
  for (const RenderFile& part : input) parts.push_back(&part);
  const auto first_sample = [](const RenderFile* part) { return metadata_number(*part, "caustica:first_sample"); };
  std::stable_sort(parts.begin(), parts.end(),
                   [&](const RenderFile* a, const RenderFile* b) { return first_sample(a) < first_sample(b); });
  const RenderFile& first = *parts.front();
  for (const RenderFile* part : parts) {
    if (!has_raw_sums(*part)) throw part_error(*part, "holds no raw sums (render it with --raw-sums)");
    check_same_render(first, *part);
    if (metadata_value(*part, "caustica:seed") != metadata_value(first, "caustica:seed"))
      throw part_error(
          *part, "has another seed than '" + first.path + "': sample ranges merge only within one seed's samples");
  }
  std::string ranges;
  double next_free = 0, spp = 0;
  for (const RenderFile* part : parts) {
    const double begin = first_sample(part), count = metadata_number(*part, "caustica:spp");
    if (part != parts.front() && begin < next_free)
      throw part_error(*part, "overlaps the sample range of another part (samples " + std::to_string(uint64_t(begin)) +
                                  " to " + std::to_string(uint64_t(begin + count) - 1) + ")");
    next_free = begin + count;
    spp += count;
    ranges += (ranges.empty() ? "" : ",") + std::to_string(uint64_t(begin)) + "-" +
              std::to_string(uint64_t(begin + count) - 1);
  }

  const Image& shape = first.image;
  FilmBuffer film(shape.width, shape.height, film_channels(first, "caustica:raw_channels"));
  const std::vector<std::string> aov_channels = film_channels(first, "caustica:raw_aov_channels");
  std::optional<FilmBuffer> aovs;
  if (!aov_channels.empty()) aovs.emplace(shape.width, shape.height, aov_channels);
  for (const RenderFile* part : parts) {
    const uint64_t paths = uint64_t(metadata_number(*part, "caustica:spp"));
    add_part(*part, kFilm, paths, film);
    if (aovs) add_part(*part, kAovs, 0, *aovs);
  }

  const bool variance_known = shape.channel_index("variance.R") >= 0;
  RenderFile merged{"", render_layers(film, aovs ? &*aovs : nullptr, variance_known, true), first.metadata};
  merged.metadata["caustica:ranges"] = ranges;
  merged.metadata["caustica:first_sample"] = metadata_value(first, "caustica:first_sample");
  merged.metadata["caustica:spp"] = std::to_string(uint64_t(spp));
  for (const char* key : {"caustica:samples", "caustica:rays"}) {
    double total = 0;
    for (const RenderFile* part : parts) total += metadata_number(*part, key);
    merged.metadata[key] = std::to_string(uint64_t(total));
  }
  double seconds = 0;
  bool interrupted = false;
  for (const RenderFile* part : parts) {
    seconds += metadata_number(*part, "caustica:seconds");
    interrupted = interrupted || metadata_value(*part, "caustica:interrupted") == "true";
  }
  merged.metadata["caustica:seconds"] = std::to_string(seconds);
  merged.metadata["caustica:interrupted"] = interrupted ? "true" : "false";
  return merged;
}

}  // namespace caustica

#include "core/job/range_merge.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/job/render_outputs.h"
#include "core/job/sample_ranges.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

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
  FilmBuffer shape(1, 1, film.channels(), film.keeps_moments() ? FilmBuffer::Moments::Kept : FilmBuffer::Moments::None);
  if (splats) shape.enable_splats();
  const std::vector<std::string> names = shape.raw_channels(prefix);
  std::vector<size_t> from;
  for (const std::string& name : names) {
    const int c = image.channel_index(name);
    if (c < 0) throw render_error(part, "lacks the raw sum " + name);
    from.push_back(size_t(c));
  }
  const size_t pixels = size_t(image.width) * image.height, nc = image.channels.size(), n = names.size();
  std::vector<float> sums(pixels * n);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t k = 0; k < n; ++k) sums[p * n + k] = image.pixels[p * nc + from[k]];
  film.add_raw(sums, splats ? splat_paths : 0);
}

struct SampleRange {
  uint64_t first, last;  // inclusive
};

// A metadata value that must be a whole number of samples.
uint64_t sample_count(const RenderFile& part, const char* key) {
  const double x = metadata_number(part, key);
  if (!(x >= 0 && x < 9.2e18 && x == std::floor(x)))
    throw render_error(part, std::string("has no sample count in its ") + key + " metadata");
  return uint64_t(x);
}

// The sample indices a render holds: its caustica:ranges if it is a merge,
// else first_sample .. first_sample + spp - 1.
std::vector<SampleRange> sample_ranges(const RenderFile& part) {
  std::vector<SampleRange> out;
  const std::string list = metadata_value(part, "caustica:ranges");
  if (list.empty()) {
    const uint64_t first = sample_count(part, "caustica:first_sample"), spp = sample_count(part, "caustica:spp");
    if (spp > 0) out.push_back({first, first + spp - 1});
    return out;
  }
  std::istringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    uint64_t first = 0, last = 0;
    char dash = 0;
    std::istringstream range(item);
    if (!(range >> first >> dash >> last) || dash != '-' || last < first)
      throw render_error(part, "has a malformed caustica:ranges entry '" + item + "'");
    out.push_back({first, last});
  }
  return out;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

bool has_raw_sums(const RenderFile& render) {
  return !film_channels(render, "caustica:raw_channels").empty() && render.image.channel_index("raw.count") >= 0;
}

bool half_float_suits(const RenderFile& render) {
  return !has_raw_sums(render) && count_extreme_values(rows_of(render.image)).beyond_half == 0;
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
  std::stable_sort(parts.begin(), parts.end(), [](const RenderFile* a, const RenderFile* b) {
    return sample_count(*a, "caustica:first_sample") < sample_count(*b, "caustica:first_sample");
  });
  const RenderFile& first = *parts.front();
  for (const RenderFile* part : parts) {
    if (!has_raw_sums(*part)) throw render_error(*part, "holds no raw sums (render it with --raw-sums)");
    check_same_render(first, *part);
    if (metadata_value(*part, "caustica:seed") != metadata_value(first, "caustica:seed"))
      throw render_error(
          *part, "has another seed than '" + first.path + "': sample ranges merge only within one seed's samples");
  }
  // Every interval of every part, the part's own included, must be disjoint.
  std::vector<std::pair<SampleRange, const RenderFile*>> intervals;
  for (const RenderFile* part : parts)
    for (const SampleRange& r : sample_ranges(*part)) intervals.emplace_back(r, part);
  std::sort(intervals.begin(), intervals.end(),
            [](const auto& a, const auto& b) { return a.first.first < b.first.first; });
  for (size_t i = 1; i < intervals.size(); ++i) {
    const auto& [r, part] = intervals[i];
    const auto& [before, other] = intervals[i - 1];
    if (r.first <= before.last)
      throw render_error(*part, "overlaps the sample range of '" + other->path + "' (samples " +
                                    std::to_string(r.first) + " to " + std::to_string(r.last) + " against " +
                                    std::to_string(before.first) + " to " + std::to_string(before.last) + ")");
  }
  std::vector<IndexRange> held;
  uint64_t spp = 0;
  for (const auto& [r, part] : intervals) {
    spp += r.last - r.first + 1;
    held.push_back({r.first, r.last - r.first + 1});
  }
  const std::vector<IndexRange> joined = joined_ranges(std::move(held));

  const Image& shape = first.image;
  FilmBuffer film(shape.width, shape.height, film_channels(first, "caustica:raw_channels"));
  const std::vector<std::string> aov_channels = film_channels(first, "caustica:raw_aov_channels");
  std::optional<FilmBuffer> aovs;
  if (!aov_channels.empty()) aovs.emplace(shape.width, shape.height, aov_channels, FilmBuffer::Moments::None);
  for (const RenderFile* part : parts) {
    const uint64_t paths = sample_count(*part, "caustica:spp");
    add_part(*part, kFilm, paths, film);
    if (aovs) add_part(*part, kAovs, 0, *aovs);
  }

  const bool variance_known = shape.channel_index("variance.R") >= 0;
  RenderFile merged{"", render_layers(film, aovs ? &*aovs : nullptr, variance_known, true), first.metadata};
  merged.metadata["caustica:ranges"] = format_ranges(joined);
  merged.metadata["caustica:first_sample"] = std::to_string(joined.front().first);
  merged.metadata["caustica:spp"] = std::to_string(spp);
  // What one part's integrator reported of its run says nothing of the others'.
  merged.metadata.erase("caustica:run");
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

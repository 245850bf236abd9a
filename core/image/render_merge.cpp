#include "core/image/render_merge.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/image/image_input.h"

namespace caustica {

std::invalid_argument render_error(const RenderFile& part, const std::string& problem) {
  return std::invalid_argument("'" + part.path + "' " + problem);
}

std::string metadata_value(const RenderFile& part, const std::string& key) {
  const auto it = part.metadata.find(key);
  return it == part.metadata.end() ? std::string() : it->second;
}

double metadata_number(const RenderFile& part, const std::string& key) {
  const std::string text = metadata_value(part, key);
  try {
    size_t used = 0;
    const double value = std::stod(text, &used);
    // Every number merged is a count or a time: a negative or non-finite
    // one is not to be trusted, nor turned into an integer.
    if (used == text.size() && value >= 0 && value < 1e18) return value;
  } catch (const std::exception&) {
  }
  throw render_error(part, "has no count below 10^18 in its " + key + " metadata (got '" + text + "')");
}

namespace {
namespace CAUSTICA_UNITY_ID {

// The number of samples in each pixel of a render.
std::vector<double> sample_counts(const RenderFile& part) {
  const Image& image = part.image;
  const size_t pixels = size_t(image.width) * image.height, nc = image.channels.size();
  const int layer = image.channel_index("samples.Y");
  if (layer < 0) return std::vector<double>(pixels, metadata_number(part, "caustica:spp"));
  std::vector<double> counts(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    const float n = image.pixels[p * nc + layer];
    if (!(n >= 0 && n == std::floor(n)))
      throw render_error(part, "has " + std::to_string(n) + " in samples.Y at pixel (" +
                                   std::to_string(p % size_t(image.width)) + ", " +
                                   std::to_string(p / size_t(image.width)) + "), not a sample count");
    counts[p] = n;
  }
  return counts;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void check_same_render(const RenderFile& first, const RenderFile& part) {
  if (part.image.width != first.image.width || part.image.height != first.image.height)
    throw render_error(part, "differs in size from '" + first.path + "'");
  if (part.image.channels != first.image.channels)
    throw render_error(part, "has other channels than '" + first.path + "'");
  for (const char* key : {"caustica:scene", "caustica:integrator"})
    if (metadata_value(part, key) != metadata_value(first, key))
      throw render_error(part, std::string("has another ") + key + " than '" + first.path + "' ('" +
                                   metadata_value(part, key) + "' against '" + metadata_value(first, key) + "')");
}

namespace {
namespace CAUSTICA_UNITY_ID {

enum class Rule { Mean, Variance, Count };

Rule rule_for(const std::string& channel) {
  if (channel == "samples.Y") return Rule::Count;
  if (channel.rfind("variance.", 0) == 0) return Rule::Variance;
  return Rule::Mean;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::vector<std::string> render_seeds(const RenderFile& render) {
  std::string list = metadata_value(render, "caustica:seeds");
  if (list.empty()) list = metadata_value(render, "caustica:seed");
  std::vector<std::string> seeds;
  std::istringstream in(list);
  for (std::string seed; std::getline(in, seed, ',');)
    if (!seed.empty()) seeds.push_back(seed);
  return seeds;
}

RenderFile read_render(const std::string& path) {
  RenderFile file{path, {}, {}};
  file.image = read_image(path, &file.metadata);
  return file;
}

namespace {
namespace CAUSTICA_UNITY_ID {

// The samples [first, end) a render of one seed holds, where its metadata
// says so; a merge of several seeds holds no one range.
std::optional<std::pair<uint64_t, uint64_t>> sample_range(const RenderFile& part) {
  if (!metadata_value(part, "caustica:seeds").empty()) return std::nullopt;
  if (metadata_value(part, "caustica:first_sample").empty() || metadata_value(part, "caustica:spp").empty())
    return std::nullopt;
  const auto first = uint64_t(metadata_number(part, "caustica:first_sample"));
  return std::pair{first, first + uint64_t(metadata_number(part, "caustica:spp"))};
}

// Why two renders of one seed cannot be merged as independent renders.
std::string shared_seed_problem(const RenderFile& a, const RenderFile& b) {
  const auto ra = sample_range(a), rb = sample_range(b);
  if (!ra || !rb || (ra->first < rb->second && rb->first < ra->second))
    return "they hold the same samples, not independent ones";
  const auto span = [](std::pair<uint64_t, uint64_t> r) {
    return std::to_string(r.first) + ".." + std::to_string(r.second - 1);
  };
  return "samples " + span(*ra) + " and " + span(*rb) +
         ": disjoint ranges of one seed merge only from their raw sums (render each with --raw-sums), or render "
         "them with different seeds to merge them as independent renders";
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

RenderFile merge_renders(const std::vector<RenderFile>& parts) {
  if (parts.empty()) throw std::invalid_argument("nothing to merge");
  const RenderFile& first = parts.front();
  std::map<std::string, const RenderFile*> seed_owner;
  for (const RenderFile& part : parts) {
    check_same_render(first, part);
    for (const std::string& seed : render_seeds(part))
      if (const auto [it, fresh] = seed_owner.emplace(seed, &part); !fresh)
        throw render_error(part, "and '" + it->second->path + "' were both rendered with seed " + seed + ": " +
                                     shared_seed_problem(part, *it->second));
  }

  const Image& shape = first.image;
  const size_t pixels = size_t(shape.width) * shape.height, nc = shape.channels.size();
  std::vector<Rule> rules;
  for (const std::string& c : shape.channels) rules.push_back(rule_for(c));
  std::vector<double> sums(pixels * nc, 0), totals(pixels, 0);
  for (const RenderFile& part : parts) {
    const std::vector<double> counts = sample_counts(part);
    for (size_t p = 0; p < pixels; ++p) {
      const double n = counts[p];
      totals[p] += n;
      for (size_t c = 0; c < nc; ++c) {
        const double v = part.image.pixels[p * nc + c];
        if (!std::isfinite(v))
          throw render_error(part, "has a value that is not finite in " + shape.channels[c] + " at pixel (" +
                                       std::to_string(p % size_t(shape.width)) + ", " +
                                       std::to_string(p / size_t(shape.width)) + ")");
        sums[p * nc + c] += rules[c] == Rule::Variance ? n * n * v : rules[c] == Rule::Count ? v : n * v;
      }
    }
  }

  RenderFile merged{
      "", {shape.width, shape.height, shape.channels, std::vector<float>(pixels * nc, 0)}, first.metadata};
  for (size_t p = 0; p < pixels; ++p) {
    const double N = totals[p];
    if (N == 0) continue;
    for (size_t c = 0; c < nc; ++c) {
      const double s = sums[p * nc + c];
      merged.image.pixels[p * nc + c] = float(rules[c] == Rule::Variance ? s / (N * N)
                                              : rules[c] == Rule::Count  ? s
                                                                         : s / N);
    }
  }

  std::string seeds;
  for (const RenderFile& part : parts)
    for (const std::string& seed : render_seeds(part)) seeds += (seeds.empty() ? "" : ",") + seed;
  merged.metadata.erase("caustica:seed");
  merged.metadata["caustica:seeds"] = seeds;
  bool interrupted = false;
  for (const RenderFile& part : parts)
    interrupted = interrupted || metadata_value(part, "caustica:interrupted") == "true";
  merged.metadata["caustica:interrupted"] = interrupted ? "true" : "false";
  for (const char* key : {"caustica:spp", "caustica:seconds", "caustica:samples", "caustica:rays"}) {
    bool everywhere = true;
    for (const RenderFile& part : parts) everywhere = everywhere && !metadata_value(part, key).empty();
    if (!everywhere) {
      merged.metadata.erase(key);
      continue;
    }
    double total = 0;
    for (const RenderFile& part : parts) total += metadata_number(part, key);
    // Counts stay integers; seconds keep render's six decimals.
    merged.metadata[key] =
        std::string(key) == "caustica:seconds" ? std::to_string(total) : std::to_string(uint64_t(total + 0.5));
  }
  return merged;
}

}  // namespace caustica

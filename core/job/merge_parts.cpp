#include "core/job/merge_parts.h"

#include <cstdio>
#include <string>
#include <vector>

#include "core/image/image_metrics.h"
#include "core/job/range_merge.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Nine significant digits: errors are tiny numbers.
std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// The part with its channels in `order` where it holds the same channels in
// another order (a file keeps them in its own order; a render in memory in
// the film's), else as it is, for check_same_render to refuse.
RenderFile in_channel_order(RenderFile part, const std::vector<std::string>& order) {
  if (part.image.channels == order || part.image.channels.size() != order.size()) return part;
  std::vector<int> from;
  for (const std::string& name : order) {
    from.push_back(part.image.channel_index(name));
    if (from.back() < 0) return part;
  }
  const size_t n = order.size();
  std::vector<float> pixels(part.image.pixels.size());
  for (size_t p = 0; p < pixels.size() / n; ++p)
    for (size_t c = 0; c < n; ++c) pixels[p * n + c] = part.image.pixels[p * n + size_t(from[c])];
  part.image.pixels = std::move(pixels);
  part.image.channels = order;
  return part;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

RenderFile merge_parts(std::vector<RenderFile> parts) {
  for (RenderFile& part : parts) part = in_channel_order(std::move(part), parts.front().image.channels);
  bool ranges = !parts.empty();
  for (const RenderFile& part : parts)
    ranges = ranges && has_raw_sums(part) && render_seeds(part) == render_seeds(parts.front());
  if (!ranges)
    for (RenderFile& part : parts) part = without_raw_sums(std::move(part));
  RenderFile merged = ranges ? merge_sample_ranges(parts) : merge_renders(parts);
  if (const EstimatedError error = estimated_error(merged.image); error.known) {
    merged.metadata["caustica:estimated_mse"] = number_text(error.mse);
    merged.metadata["caustica:estimated_rel_mse"] = number_text(error.rel_mse);
  }
  return merged;
}

}  // namespace caustica

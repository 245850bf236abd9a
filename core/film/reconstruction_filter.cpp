#include "core/film/reconstruction_filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {
constexpr int kCells = 256;
constexpr int kSubsamples = 16;
}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void ReconstructionFilter::init(float radius) {
  radius_ = radius;
  cell_.assign(kCells, 0);
  cdf_.assign(kCells + 1, 0);
  const float width = 2 * radius / kCells;
  for (int i = 0; i < kCells; ++i) {
    float sum = 0;
    for (int k = 0; k < kSubsamples; ++k) sum += std::abs(eval(-radius + (i + (k + 0.5f) / kSubsamples) * width));
    cell_[i] = sum / kSubsamples * width;
    cdf_[i + 1] = cdf_[i] + cell_[i];
  }
  if (!(cdf_.back() > 0)) throw std::invalid_argument("reconstruction filter integrates to zero");
  guide_.resize(kCells);
  for (int g = 0; g < kCells; ++g) {
    // Float products are monotonic in u, so every target of slice g is at
    // least this one, and the scan may start from its cell.
    const float slice_start = float(g) / kCells * cdf_.back();
    guide_[g] = std::max(int(std::upper_bound(cdf_.begin(), cdf_.end(), slice_start) - cdf_.begin()) - 1, 0);
  }
}

float ReconstructionFilter::sample_1d(float u, float* weight) const {
  const float target = u * cdf_.back();
  int above = guide_[std::clamp(int(u * kCells), 0, kCells - 1)] + 1;
  while (above <= kCells && cdf_[above] <= target) ++above;
  const int i = std::clamp(above - 1, 0, kCells - 1);
  const float width = 2 * radius_ / kCells;
  const float frac = cell_[i] > 0 ? (target - cdf_[i]) / cell_[i] : 0.5f;
  const float x = -radius_ + (i + std::clamp(frac, 0.0f, 1.0f)) * width;
  // Density of x under the tabulation: cell mass / total / width.
  const float pdf = cell_[i] / (cdf_.back() * width);
  *weight = pdf > 0 ? eval(x) / pdf : 0;
  return x;
}

FilterSample ReconstructionFilter::sample(Vec2 u) const {
  float wx = 0, wy = 0;
  const float x = sample_1d(u.x, &wx), y = sample_1d(u.y, &wy);
  return {{x, y}, wx * wy};
}

}  // namespace caustica

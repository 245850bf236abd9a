#include "integrators/path/guiding/directional_quadtree.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kBelowOne = 1 - 0x1p-53;

// Which half of [0, 1) the coordinate u falls in when the lower half holds
// `lower` of the energy, and u rescaled to cover [0, 1) within that half.
int choose_half(double& u, double lower) {
  if (u < lower) {
    u = std::min(u / lower, kBelowOne);
    return 0;
  }
  u = std::min((u - lower) / (1 - lower), kBelowOne);
  return 1;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Vec2 direction_to_square(Vec3 w) {
  const float z = std::clamp(w.z, -1.0f, 1.0f);
  float phi = std::atan2(w.y, w.x) * (0.5f * kInvPi);
  if (phi < 0) phi += 1;
  return {std::min((z + 1) * 0.5f, std::nextafter(1.0f, 0.0f)), std::min(phi, std::nextafter(1.0f, 0.0f))};
}

Vec3 square_to_direction(Vec2 p) {
  const float z = 2 * p.x - 1;
  const float r = std::sqrt(std::max(0.0f, 1 - z * z));
  const float phi = 2 * kPi * p.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

DirectionalDistribution::DirectionalDistribution(QuadtreeShape shape, std::vector<std::array<double, 4>> energy)
    : shape_(std::move(shape)), energy_(std::move(energy)), steps_(shape_.nodes()) {
  const auto& root = energy_[0];
  total_ = root[0] + root[1] + root[2] + root[3];
  for (size_t n = 0; n < steps_.size(); ++n) {
    const auto& e = energy_[n];
    const double sum = e[0] + e[1] + e[2] + e[3];
    Step& step = steps_[n];
    step.children = shape_.children[n];
    if (!(sum > 0)) {
      step.density = {};
      step.lower_x = step.lower_y[0] = step.lower_y[1] = 0.5f;
      continue;
    }
    for (int q = 0; q < 4; ++q) step.density[q] = float(4 * e[q] / sum);
    step.lower_x = float((e[0] + e[2]) / sum);
    for (int qx = 0; qx < 2; ++qx) {
      const double column = e[qx] + e[qx + 2];
      step.lower_y[qx] = column > 0 ? float(e[qx] / column) : 0.5f;
    }
  }
}

DirectionalDistribution::Sample DirectionalDistribution::sample(Vec2 u_in) const {
  double u = u_in.x, v = u_in.y;
  if (empty()) return {u_in, 1, {0, 0}, 1};
  double x0 = 0, y0 = 0, size = 1;
  float pdf = 1;
  for (uint32_t node = 0;;) {
    const Step& step = steps_[node];
    const int qx = choose_half(u, step.lower_x);
    const int qy = choose_half(v, step.lower_y[qx]);
    const int q = qx + 2 * qy;
    pdf *= step.density[q];
    size *= 0.5;
    x0 += qx * size;
    y0 += qy * size;
    node = step.children[q];
    if (node == 0) break;
  }
  // The leaf's corners are multiples of a power of two that floats hold
  // exactly; rounding must not carry the point into the next quadrant.
  const auto inside = [size](double lo, double t) {
    return std::min(float(lo + t * size), std::nextafter(float(lo + size), 0.0f));
  };
  return {{inside(x0, u), inside(y0, v)}, pdf, {float(x0), float(y0)}, float(size)};
}

float DirectionalDistribution::pdf(Vec2 p) const {
  if (empty()) return 1;
  float x = p.x, y = p.y, pdf = 1;
  for (uint32_t node = 0;;) {
    const Step& step = steps_[node];
    const int qx = x >= 0.5f ? 1 : 0, qy = y >= 0.5f ? 1 : 0;
    const int q = qx + 2 * qy;
    pdf *= step.density[q];
    if (!(pdf > 0)) return 0;
    x = 2 * x - float(qx);
    y = 2 * y - float(qy);
    node = step.children[q];
    if (node == 0) break;
  }
  return pdf;
}

size_t DirectionalDistribution::bytes() const {
  return sizeof(DirectionalDistribution) +
         shape_.nodes() * (sizeof(std::array<uint32_t, 4>) + sizeof(std::array<double, 4>) + sizeof(Step));
}

DirectionalRecorder::DirectionalRecorder(QuadtreeShape shape)
    : shape_(std::move(shape)), sums_(new std::array<FixedPointSum, 4>[shape_.nodes()]()) {}

void DirectionalRecorder::record(Vec2 p, double energy) {
  float x = p.x, y = p.y;
  for (uint32_t node = 0;;) {
    const int qx = x >= 0.5f ? 1 : 0, qy = y >= 0.5f ? 1 : 0;
    const int q = qx + 2 * qy;
    const uint32_t child = shape_.children[node][q];
    if (child == 0) {
      sums_[node][q].add(energy);
      return;
    }
    x = 2 * x - float(qx);
    y = 2 * y - float(qy);
    node = child;
  }
}

void DirectionalRecorder::record_spread(Vec2 p, double energy) {
  double size = 1, x = p.x, y = p.y;
  for (uint32_t node = 0;;) {
    const int qx = x >= 0.5 ? 1 : 0, qy = y >= 0.5 ? 1 : 0;
    size /= 2;
    node = shape_.children[node][qx + 2 * qy];
    if (node == 0) break;
    x = 2 * x - qx;
    y = 2 * y - qy;
  }
  const double box[4] = {p.x - size / 2, p.y - size / 2, p.x + size / 2, p.y + size / 2};
  splat(0, 0, 0, 1, box, energy / (size * size));
}

void DirectionalRecorder::splat(uint32_t node, double x0, double y0, double size, const double box[4], double density) {
  const double half = size / 2;
  for (int q = 0; q < 4; ++q) {
    const double qx0 = x0 + (q & 1) * half, qy0 = y0 + (q >> 1) * half;
    const double w = std::min(box[2], qx0 + half) - std::max(box[0], qx0);
    const double h = std::min(box[3], qy0 + half) - std::max(box[1], qy0);
    if (!(w > 0 && h > 0)) continue;
    const uint32_t child = shape_.children[node][q];
    if (child == 0)
      sums_[node][q].add(density * w * h);
    else
      splat(child, qx0, qy0, half, box, density);
  }
}

DirectionalDistribution DirectionalRecorder::distribution() const {
  std::vector<std::array<double, 4>> energy(shape_.nodes());
  // Children come after their parents, so a backward sweep sums them first.
  for (size_t n = shape_.nodes(); n-- > 0;)
    for (int q = 0; q < 4; ++q) {
      const uint32_t child = shape_.children[n][q];
      const auto& c = energy[child];
      energy[n][q] = child == 0 ? sums_[n][q].value() : c[0] + c[1] + c[2] + c[3];
    }
  return {shape_, std::move(energy)};
}

size_t DirectionalRecorder::bytes_for(const QuadtreeShape& shape) {
  return sizeof(DirectionalRecorder) +
         shape.nodes() * (sizeof(std::array<uint32_t, 4>) + sizeof(std::array<FixedPointSum, 4>));
}

namespace {
namespace CAUSTICA_UNITY_ID {

void refine(const DirectionalDistribution& d, const std::array<double, 4>& energy, uint32_t from, double total,
            double threshold, int depth, int max_depth, QuadtreeShape& out, uint32_t into) {
  for (int q = 0; q < 4; ++q) {
    if (!(energy[q] > threshold * total) || depth >= max_depth) continue;
    const uint32_t old_child = from == UINT32_MAX ? 0 : d.shape().children[from][q];
    const uint32_t child = uint32_t(out.children.size());
    out.children.push_back({0, 0, 0, 0});
    out.children[into][q] = child;
    if (old_child != 0) {
      refine(d, d.energy(old_child), old_child, total, threshold, depth + 1, max_depth, out, child);
    } else {
      const double quarter = energy[q] / 4;
      refine(d, {quarter, quarter, quarter, quarter}, UINT32_MAX, total, threshold, depth + 1, max_depth, out, child);
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

QuadtreeShape refined_shape(const DirectionalDistribution& d, double threshold, int max_depth) {
  QuadtreeShape out;
  if (d.empty()) return out;
  refine(d, d.energy(0), 0, d.total(), threshold, 1, max_depth, out, 0);
  return out;
}

}  // namespace caustica

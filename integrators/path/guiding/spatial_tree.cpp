#include "integrators/path/guiding/spatial_tree.h"

#include <algorithm>
#include <cmath>

namespace caustica {

int normal_bucket(Vec3 n) {
  const Vec3 a{std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return 2 * axis + (n[axis] < 0 ? 1 : 0);
}

GuidingTree::GuidingTree(const Bounds3& b) : nodes_(1) {
  regions_.emplace_back();
  if (b.empty()) {
    lo_ = {-1, -1, -1};
    size_ = 2;
    return;
  }
  const Vec3 extent = b.hi - b.lo;
  // A little larger than the scene, so that points on its bounds fall inside.
  size_ = std::max({extent.x, extent.y, extent.z, 1e-6f}) * 1.001f;
  lo_ = b.center() - Vec3(size_ / 2, size_ / 2, size_ / 2);
}

GuidingRegion& GuidingTree::region_at(Vec3 p) {
  const float below_one = std::nextafter(1.0f, 0.0f);
  float t[3];
  for (int a = 0; a < 3; ++a) t[a] = std::clamp((p[a] - lo_[a]) / size_, 0.0f, below_one);
  uint32_t n = 0;
  for (int depth = 0; nodes_[n].children[0] != 0; ++depth) {
    float& x = t[depth % 3];
    const int half = x >= 0.5f ? 1 : 0;
    x = 2 * x - float(half);
    n = nodes_[n].children[half];
  }
  return regions_[nodes_[n].region];
}

size_t GuidingTree::directional_nodes() const {
  size_t n = 0;
  for (const GuidingRegion& r : regions_)
    for (const DirectionalGuide& g : r.guides) n += g.sampling.shape().nodes() + g.recording.shape().nodes();
  return n;
}

size_t GuidingTree::guides_without_lights() const {
  size_t n = 0;
  for (const GuidingRegion& r : regions_)
    for (const DirectionalGuide& g : r.guides) n += g.lights_unseen ? 1 : 0;
  return n;
}

size_t GuidingTree::bytes() const {
  size_t b = nodes_.size() * sizeof(Node);
  for (const GuidingRegion& r : regions_) {
    b += sizeof(GuidingRegion);
    for (const DirectionalGuide& g : r.guides) b += g.sampling.bytes() + g.recording.bytes() - sizeof g;
  }
  return b;
}

void GuidingTree::refine(const GuidingRefinement& settings, uint64_t pass_spp) {
  struct Recorded {
    std::array<DirectionalDistribution, kNormalBuckets> distributions;
    std::array<uint64_t, kNormalBuckets> bucket_records;
    std::array<float, kNormalBuckets> radiance;
    std::array<bool, kNormalBuckets> lights_unseen;
    uint64_t records;
  };
  std::vector<Recorded> recorded;
  recorded.reserve(regions_.size());
  for (const GuidingRegion& r : regions_) {
    Recorded& out = recorded.emplace_back();
    for (int b = 0; b < kNormalBuckets; ++b) {
      out.distributions[b] = r.guides[b].recording.distribution();
      out.bucket_records[b] = r.guides[b].records.load();
      const DirectionalGuide& g = r.guides[b];
      const uint64_t n = g.radiance_records.load();
      out.radiance[b] = n >= kMinRadianceRecords ? float(g.radiance_sum.value() / double(n)) : g.radiance;
      out.lights_unseen[b] = g.light_samples.load() >= kMinLightSamples ? g.lit_samples.load() == 0 : g.lights_unseen;
    }
    out.records = r.records.load();
  }

  // A region's cost once its recorders take the shapes of its distributions.
  const auto region_bytes = [](const Recorded& r) {
    size_t b = sizeof(GuidingRegion);
    for (const DirectionalDistribution& d : r.distributions)
      b += d.bytes() + DirectionalRecorder::bytes_for(d.shape()) - sizeof(DirectionalGuide);
    return b;
  };
  size_t bytes = 0;
  for (const Recorded& r : recorded) bytes += region_bytes(r);
  bytes += nodes_.size() * sizeof(Node);

  capped_ = false;
  const double split_above = settings.spatial_threshold * std::sqrt(double(pass_spp));
  std::vector<int> depth(nodes_.size(), 0);
  for (size_t n = 1; n < nodes_.size(); ++n) depth[n] = -1;
  // Parents come before their children, so one forward sweep sees every
  // node's depth and halves new leaves again where they still hold too many.
  for (size_t n = 0; n < nodes_.size(); ++n) {
    for (uint32_t c : nodes_[n].children)
      if (c != 0) depth[c] = depth[n] + 1;
    if (nodes_[n].children[0] != 0) continue;
    Recorded& r = recorded[nodes_[n].region];
    if (!(double(r.records) > split_above) || depth[n] >= settings.max_spatial_depth) continue;
    const size_t more = region_bytes(r) + 2 * sizeof(Node);
    if (bytes + more > settings.max_bytes) {
      capped_ = true;
      continue;
    }
    bytes += more;
    // Each half's count predicts its next pass's records; both halves'
    // guides still learn from every record of the whole.
    r.records /= 2;
    const auto first = uint32_t(nodes_.size());
    nodes_.push_back({{0, 0}, nodes_[n].region});
    nodes_.push_back({{0, 0}, uint32_t(recorded.size())});
    recorded.push_back(recorded[nodes_[n].region]);
    nodes_[n].children = {first, first + 1};
    depth.push_back(depth[n] + 1);
    depth.push_back(depth[n] + 1);
  }

  regions_.clear();
  for (Recorded& r : recorded) {
    GuidingRegion& region = regions_.emplace_back();
    for (int b = 0; b < kNormalBuckets; ++b) {
      DirectionalDistribution& d = r.distributions[b];
      QuadtreeShape shape = refined_shape(d, settings.directional_threshold, settings.max_directional_depth);
      // The bytes so far counted the recorder in the distribution's shape.
      const size_t now = DirectionalRecorder::bytes_for(d.shape());
      const size_t after = DirectionalRecorder::bytes_for(shape);
      const size_t more = after > now ? after - now : 0;
      if (bytes + more > settings.max_bytes) {
        capped_ = true;
        shape = d.shape();
      } else {
        bytes += more;
      }
      region.guides[b].recording = DirectionalRecorder(std::move(shape));
      region.guides[b].radiance = r.radiance[b];
      region.guides[b].lights_unseen = r.lights_unseen[b];
      if (r.bucket_records[b] >= settings.min_records) region.guides[b].sampling = std::move(d);
    }
  }
}

}  // namespace caustica

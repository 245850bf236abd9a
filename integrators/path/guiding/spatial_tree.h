#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <vector>

#include "core/geometry/bounds.h"
#include "integrators/path/guiding/directional_quadtree.h"

namespace caustica {

// How the guiding distribution is refined between passes (Müller, Gross,
// Novák 2017, "Practical path guiding").
struct GuidingRefinement {
  // A region is halved once it holds more than spatial_threshold *
  // sqrt(samples per pixel of the pass) records.
  double spatial_threshold = 12000;
  // A directional quadrant is divided once it holds more than this share of
  // its region's energy.
  double directional_threshold = 0.01;
  int max_directional_depth = 20;
  int max_spatial_depth = 48;
  // Refinement stops where the trees would need more bytes than this.
  size_t max_bytes = size_t(256) << 20;
};

// A region of space with the directional distribution its paths sample by
// in this pass and the recorder of what they find for the next one.
struct GuidingRegion {
  DirectionalDistribution sampling;
  DirectionalRecorder recording;
  std::atomic<uint64_t> records{0};

  void record(Vec2 direction, double energy) {
    recording.record(direction, energy);
    records.fetch_add(1, std::memory_order_relaxed);
  }
};

// A binary tree over a cube around the scene, halving its regions along x,
// y and z in turn, with a GuidingRegion in each leaf.
class GuidingTree {
 public:
  explicit GuidingTree(const Bounds3& scene_bounds);

  GuidingRegion& region_at(Vec3 p);
  // From the records of a pass of `pass_spp` samples per pixel: regions
  // holding many records are halved (both halves taking the records'
  // distribution), the records become every region's sampling
  // distribution, and each recorder is reshaped for the next pass.
  void refine(const GuidingRefinement& settings, uint64_t pass_spp);

  size_t regions() const { return regions_.size(); }
  size_t directional_nodes() const;
  size_t bytes() const;
  // Whether the byte cap held refinement back in the last refine().
  bool capped() const { return capped_; }

 private:
  struct Node {
    std::array<uint32_t, 2> children{0, 0};  // both 0 for a leaf
    uint32_t region = 0;
  };
  Vec3 lo_;
  float size_;
  std::vector<Node> nodes_;
  std::deque<GuidingRegion> regions_;
  bool capped_ = false;
};

}  // namespace caustica

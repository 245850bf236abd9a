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
  double spatial_threshold = 4000;
  // A directional quadrant is divided once it holds more than this share of
  // its region's energy.
  double directional_threshold = 0.01;
  // A guide learnt from fewer records than this is left empty, and its
  // paths sample the BSDF alone: a few records make a spiky distribution,
  // and every BSDF-sampled direction it gives no density to weighs up to
  // 1 / bsdf_fraction of what it would under the BSDF alone, a factor that
  // compounds over the path's vertices into rare, very bright samples.
  uint64_t min_records = 128;
  int max_directional_depth = 20;
  int max_spatial_depth = 48;
  // Refinement stops where the trees would need more bytes than this.
  size_t max_bytes = size_t(256) << 20;
};

// The directional distribution a region's paths sample by in this pass and
// the recorder of what they find for the next one.
struct DirectionalGuide {
  DirectionalDistribution sampling;
  DirectionalRecorder recording;
  std::atomic<uint64_t> records{0};  // recorded this pass
  // The radiance the region's surfaces send back along camera paths (all
  // that a path gathered from a vertex on, over its weight there), learnt
  // as a mean over the last pass that recorded at least
  // kMinRadianceRecords of it; 0 while unknown. Adjoint-driven roulette
  // weighs paths by it.
  float radiance = 0;
  FixedPointSum radiance_sum;  // this pass's
  std::atomic<uint64_t> radiance_records{0};

  void record_radiance(double L) {
    radiance_sum.add(L);
    radiance_records.fetch_add(1, std::memory_order_relaxed);
  }

  // Whether light samples from the region's surfaces never reach a light
  // (occluded, or behind the surface): learnt once a pass took
  // kMinLightSamples of them and none added anything, and kept since
  // (guided paths then take none there, so later passes take too few to
  // judge again).
  bool lights_unseen = false;
  std::atomic<uint64_t> light_samples{0}, lit_samples{0};  // this pass's

  void record_light_sample(bool lit) {
    light_samples.fetch_add(1, std::memory_order_relaxed);
    if (lit) lit_samples.fetch_add(1, std::memory_order_relaxed);
  }
};
inline constexpr uint64_t kMinRadianceRecords = 16;
inline constexpr uint64_t kMinLightSamples = 256;

// Surfaces facing apart see light from apart: a region keeps one guide for
// the points whose normal (turned toward the path's side) lies nearest
// each of +x, -x, +y, -y, +z and -z, so that a floor and the wall beside it
// in one region do not send each other's paths into their own backs.
inline constexpr int kNormalBuckets = 6;
int normal_bucket(Vec3 n);

// A region of space, its guides and how many records it took this pass.
struct GuidingRegion {
  std::array<DirectionalGuide, kNormalBuckets> guides;
  std::atomic<uint64_t> records{0};

  // Energy for the directional distribution, and a count toward halving
  // the region.
  void record(int bucket, Vec2 direction, double energy) {
    guides[bucket].recording.record_spread(direction, energy);
    guides[bucket].records.fetch_add(1, std::memory_order_relaxed);
    count();
  }
  // Where light paths teach the directions, camera paths only count: both
  // kinds of path then decide where regions are fine.
  void count() { records.fetch_add(1, std::memory_order_relaxed); }
};

// A binary tree over a cube around the scene, halving its regions along x,
// y and z in turn, with a GuidingRegion in each leaf.
class GuidingTree {
 public:
  explicit GuidingTree(const Bounds3& scene_bounds);

  GuidingRegion& region_at(Vec3 p);
  // From the records of a pass of `pass_spp` samples per pixel: regions
  // holding many records are halved (both halves taking what the whole
  // learnt), the records become every region's sampling distribution,
  // radiance and whether its light samples reach a light, and each
  // recorder is reshaped for the next pass.
  void refine(const GuidingRefinement& settings, uint64_t pass_spp);

  size_t regions() const { return regions_.size(); }
  size_t directional_nodes() const;
  // The guides that have learnt that their light samples reach no light.
  size_t guides_without_lights() const;
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

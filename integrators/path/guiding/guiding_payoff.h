#pragma once

#include <cstdint>
#include <vector>

#include "core/math/color.h"
#include "core/math/vec.h"

namespace caustica {

// What one sample's walk cost: its surface vertices, and how many of them
// read the guiding trees (a region's look-up, and the quadtree's density at
// each direction the vertex sampled or connected along).
struct WalkCost {
  uint64_t vertices = 0;
  uint64_t guided = 0;
};

// Whether guided paths pay for themselves on this scene, judged from the
// training passes' own samples: pass 0 is unguided, each later one guided,
// and every one unbiased, so the two estimators differ only in variance
// and cost. After guided pass k, the relative variance per sample of pass
// k and of pass 0 (each pixel's variance over its squared mean plus
// kRelMseEpsilon, averaged over pixels and channels: the error bench/
// scores), each times its cost per sample, say which reaches a given error
// sooner. The cost counts vertices, a guided one as 1 + kGuidedVertexExtra:
// counts, unlike clocks, are deterministic, and with sums per pixel in
// sample order every thread count and every MPI rank reaches the same
// verdict.
//
// Pass k's variance is its own samples' (2^k per pixel). Pass 0 has one
// sample per pixel, so its variance is read as its squared distance to the
// mean of passes 1..k, less that mean's variance. Both are weighed by the
// mean of passes 1..k. Heavy tails make the figures noisy, and a pass of
// few samples misses more of its tail, so the first passes judged
// understate guided variance (docs/integrators.md, "Only where it pays").
class GuidingPayoff {
 public:
  static constexpr uint32_t kFirstJudged = 2;
  // A guided vertex's extra cost in unguided vertices. Measured with
  // bench/guiding.py's scenes on one thread: guided / unguided seconds per
  // sample 1.77 (cornell-box) and 1.45 (door-ajar) where the vertices per
  // sample were 1.18 and 1.0 times as many, nearly all guided.
  static constexpr double kGuidedVertexExtra = 0.5;

  GuidingPayoff(int width, int height);

  // Before the samples of training pass `pass` (passes come in order).
  void begin_pass(uint32_t pass);
  // One sample of the current pass (the part of its radiance that guiding
  // can change) and what its walk cost. Safe from many
  // threads as long as each pixel's samples come from one thread, in order:
  // only the tracked pixels keep anything, their cost included, so no two
  // threads write one place.
  void add(Vec2i pixel, const Color& L, const WalkCost& cost);

  // Relative variance and cost per sample of pass 0 and of the last.
  struct Verdict {
    double unguided_variance = 0, unguided_cost = 0;
    double guided_variance = 0, guided_cost = 0;
    bool pays() const { return guided_variance * guided_cost < unguided_variance * unguided_cost; }
  };
  // After every sample of a guided pass from kFirstJudged on.
  Verdict judge() const;

 private:
  struct Pixel {
    double first[3];    // pass 0's sample
    double earlier[3];  // the sum of passes 1 .. k-1
    double sum[3];      // the current pass's sum
    double squares[3];  // and sum of squares
    // The current pass's samples and what their walks cost.
    uint64_t samples, vertices, guided;
  };
  Pixel* tracked(Vec2i p);
  double cost_per_sample() const;

  int stride_;  // every stride_-th pixel along x and y is tracked, at most 65536 of them
  int columns_;
  std::vector<Pixel> pixels_;
  uint32_t pass_ = 0;
  double pass0_cost_ = 0;
};

}  // namespace caustica

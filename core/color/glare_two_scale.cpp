#include "core/color/glare_two_scale.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/color/glare_psf.h"
#include "core/image/fft_convolution.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The near part's share of the kernel at distance rho: all of it up to
// 96 pixels, none from 224 on (inside the near reach), smoothstep between.
// The far part's interpolation error falls as the square of the block
// size over the distance, so the hand-over sits well out.
double near_share(double rho) {
  constexpr double kInner = 96, kOuter = 224;
  if (rho <= kInner) return 1;
  if (rho >= kOuter) return 0;
  const double t = (kOuter - rho) / (kOuter - kInner);
  return t * t * (3 - 2 * t);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

BlockNeighbours block_neighbours(int i, int blocks) {
  constexpr int f = kGlareBlock;
  const float u = (float(i) - float(f - 1) / 2) / float(f);
  const int lo = std::clamp(int(std::floor(u)), 0, blocks - 1);
  return {lo, std::min(lo + 1, blocks - 1), std::clamp(u - float(lo), 0.0f, 1.0f)};
}

void spread_two_scale(std::vector<float>& rgb, int width, int height, double degrees_per_pixel) {
  constexpr int f = kGlareBlock;
  const PsfPixelIntegral psf(width, height, degrees_per_pixel);

  const int near_w = std::min(kGlareNearReach, width), near_h = std::min(kGlareNearReach, height);
  EvenKernel near{near_w, near_h, std::vector<double>(size_t(near_w) * near_h)};
  tbb::parallel_for(0, near_h, [&](int dy) {
    for (int dx = 0; dx < near_w; ++dx)
      near.quadrant[size_t(dy) * near_w + dx] = near_share(std::hypot(dx, dy)) * psf(dx, dy);
  });

  const int blocks_x = (width + f - 1) / f, blocks_y = (height + f - 1) / f;
  EvenKernel far{blocks_x, blocks_y, std::vector<double>(size_t(blocks_x) * blocks_y)};
  tbb::parallel_for(0, blocks_y, [&](int by) {
    for (int bx = 0; bx < blocks_x; ++bx) {
      const int dx = f * bx, dy = f * by;
      const double share = 1 - near_share(std::hypot(dx, dy));
      if (share > 0 && dx < width && dy < height) far.quadrant[size_t(by) * blocks_x + bx] = share * psf(dx, dy);
    }
  });
  // Each centre gathers for f^2 pixels' worth of weight, so f^2 times the
  // centres' weights is the far part's sum.
  const double total = near.total() + double(f) * f * far.total();
  for (double& w : near.quadrant) w /= total;
  for (double& w : far.quadrant) w /= total;

  std::vector<float> centres(size_t(blocks_x) * blocks_y * 3, 0.0f);
  const auto centre = [&](int bx, int by, int c) -> float& { return centres[(size_t(by) * blocks_x + bx) * 3 + c]; };
  // Each row of centres takes its light from the pixel rows around it
  // only, so the rows fill in parallel without sharing a write.
  tbb::parallel_for(0, blocks_y, [&](int by) {
    for (int y = std::max(0, f * (by - 1)); y < std::min(height, f * (by + 2)); ++y) {
      const BlockNeighbours b = block_neighbours(y, blocks_y);
      const float share = (b.lo == by ? 1 - b.t : 0.0f) + (b.hi == by ? b.t : 0.0f);
      if (share == 0) continue;
      for (int x = 0; x < width; ++x) {
        const BlockNeighbours a = block_neighbours(x, blocks_x);
        for (int c = 0; c < 3; ++c) {
          const float light = share * rgb[(size_t(y) * width + x) * 3 + c];
          centre(a.lo, by, c) += (1 - a.t) * light;
          centre(a.hi, by, c) += a.t * light;
        }
      }
    }
  });
  convolve(centres, blocks_x, blocks_y, 3, far);
  convolve(rgb, width, height, 3, near);

  tbb::parallel_for(0, height, [&](int y) {
    const BlockNeighbours b = block_neighbours(y, blocks_y);
    for (int x = 0; x < width; ++x) {
      const BlockNeighbours a = block_neighbours(x, blocks_x);
      for (int c = 0; c < 3; ++c) {
        const float top = centre(a.lo, b.lo, c) + a.t * (centre(a.hi, b.lo, c) - centre(a.lo, b.lo, c));
        const float bottom = centre(a.lo, b.hi, c) + a.t * (centre(a.hi, b.hi, c) - centre(a.lo, b.hi, c));
        rgb[(size_t(y) * width + x) * 3 + c] += top + b.t * (bottom - top);
      }
    }
  });
}

}  // namespace caustica

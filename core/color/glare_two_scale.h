#pragma once

#include <vector>

namespace caustica {

// Spreads pixel-interleaved RGB by the normalised glare kernel of
// glare_kernel() in two scales, for large images where the exact
// convolution's transforms (twice the image on each axis) cost seconds.
// The kernel is split smoothly by distance: up to kGlareNearReach pixels
// it is convolved exactly, with transforms only the reach larger than the
// image; the rest, smooth at that distance, acts between the centres of
// kGlareBlock x kGlareBlock blocks, with the kernel's value at the centres'
// offset. Each pixel's light goes to the four nearest centres by bilinear
// weights and each pixel takes its glare from them the same way, so a
// light's amount and centroid are kept and the error is second order in
// the block size. Its error against the exact convolution is measured in
// tests/color/glare_two_scale_test.cpp.
void spread_two_scale(std::vector<float>& rgb, int width, int height, double degrees_per_pixel);

inline constexpr int kGlareNearReach = 256;
inline constexpr int kGlareBlock = 8;

// Where pixel i of a row or column lies between block centres (at
// (kGlareBlock - 1) / 2 within each block): the centres lo and hi and the
// weight t of hi. Beyond the outer centres a pixel belongs wholly to the
// outer one.
struct BlockNeighbours {
  int lo, hi;
  float t;
};
BlockNeighbours block_neighbours(int i, int blocks);

}  // namespace caustica

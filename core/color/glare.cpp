#include "core/color/glare.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/color/glare_psf.h"
#include "core/color/glare_two_scale.h"
#include "core/image/fft_convolution.h"

namespace caustica {

GlareMode parse_glare_mode(const std::string& name) {
  if (name == "none") return GlareMode::None;
  if (name == "whole") return GlareMode::Whole;
  if (name == "clipped") return GlareMode::Clipped;
  throw std::invalid_argument("glare must be none, whole or clipped, not '" + name + "'");
}

const char* glare_mode_name(GlareMode mode) {
  switch (mode) {
    case GlareMode::Whole:
      return "whole";
    case GlareMode::Clipped:
      return "clipped";
    case GlareMode::None:
      break;
  }
  return "none";
}

namespace {
namespace CAUSTICA_UNITY_ID {

// Large enough for any light, small enough that sums over a whole image
// in the transforms stay finite.
constexpr float kLargestRadiance = 1e30f;

float finite_radiance(float v) { return v > 0 ? std::min(v, kLargestRadiance) : 0.0f; }

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

bool apply_glare(std::vector<float>& rgb, int width, int height, const Glare& glare) {
  if (glare.mode == GlareMode::None) return false;
  if (!(glare.degrees_per_pixel > 0) || !std::isfinite(glare.degrees_per_pixel))
    throw std::invalid_argument("glare needs a camera with a field of view (degrees per pixel above 0)");
  const auto each_row = [&](auto&& body) {
    tbb::parallel_for(0, height, [&](int y) {
      for (size_t i = size_t(y) * width * 3; i < size_t(y + 1) * width * 3; ++i) body(i);
    });
  };
  const auto spread_by_psf = [&](std::vector<float>& light) {
    if (std::min(width, height) >= kGlareTwoScaleFrom)
      spread_two_scale(light, width, height, glare.degrees_per_pixel);
    else
      convolve(light, width, height, 3, glare_kernel(width, height, glare.degrees_per_pixel));
  };
  each_row([&](size_t i) { rgb[i] = finite_radiance(rgb[i]); });
  // The transforms' rounding can leave dark pixels a hair below zero.
  if (glare.mode == GlareMode::Whole) {
    spread_by_psf(rgb);
    each_row([&](size_t i) { rgb[i] = std::max(rgb[i], 0.0f); });
    return true;
  }
  std::vector<float> spread(rgb.size(), 0.0f);
  bool beyond = false;
  for (size_t p = 0; p + 2 < rgb.size(); p += 3) {
    const float largest = std::max({rgb[p], rgb[p + 1], rgb[p + 2]});
    if (largest <= 1) continue;
    beyond = true;
    for (size_t c = p; c < p + 3; ++c) {
      spread[c] = rgb[c] * (1 - 1 / largest);
      rgb[c] /= largest;
    }
  }
  if (!beyond) return false;
  spread_by_psf(spread);
  each_row([&](size_t i) { rgb[i] += std::max(spread[i], 0.0f); });
  return true;
}

}  // namespace caustica

#pragma once

#include <string>
#include <vector>

namespace caustica {

// Glare: the light a bright source scatters in the eye, spread over the
// image by the eye's point spread function (core/color/glare_psf.h).
// `whole` spreads every pixel's light, as an eye would see the scene;
// `clipped` spreads only what lies beyond the display's range (a pixel's
// largest channel above 1 after exposure: the pixel keeps its colour
// scaled to reach 1, the rest is spread), so everything the display can
// show is left as it is.
enum class GlareMode { None, Whole, Clipped };

// "none", "whole" or "clipped"; anything else throws std::invalid_argument.
GlareMode parse_glare_mode(const std::string& name);
const char* glare_mode_name(GlareMode mode);

struct Glare {
  GlareMode mode = GlareMode::None;
  double degrees_per_pixel = 0;
};

// In place on pixel-interleaved, scene-linear RGB. Returns false where
// nothing was spread: mode none, or clipped with no pixel beyond the range
// (then no transform is computed either). NaN and negative values count
// as black, infinities as the largest finite radiance. Images at least
// kGlareTwoScaleFrom pixels on each side are spread in two scales
// (core/color/glare_two_scale.h), smaller ones exactly.
inline constexpr int kGlareTwoScaleFrom = 512;
bool apply_glare(std::vector<float>& rgb, int width, int height, const Glare& glare);

}  // namespace caustica

#include "core/color/developer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace caustica {

std::array<size_t, 3> beauty_channels(const Image& image) {
  const auto find = [&](const char* name) {
    return size_t(std::find(image.channels.begin(), image.channels.end(), name) - image.channels.begin());
  };
  const std::array<size_t, 3> named = {find("R"), find("G"), find("B")};
  if (named[0] < image.channels.size() && named[1] < image.channels.size() && named[2] < image.channels.size())
    return named;
  return {0, 1, 2};
}

std::vector<float> Developer::develop(Image image, bool* glare_spread) const {
  const size_t pixels = size_t(image.width) * image.height;
  const size_t nc = image.channels.size();
  const float scale = std::exp2(op_->exposure());
  const auto source = beauty_channels(image);
  std::vector<float> rgb;
  if (nc == 3 && source == std::array<size_t, 3>{0, 1, 2}) {
    rgb = std::move(image.pixels);
    for (float& v : rgb) v *= scale;
  } else {
    rgb.assign(pixels * 3, 0.0f);
    for (size_t p = 0; p < pixels; ++p)
      for (size_t c = 0; c < 3; ++c)
        if (source[c] < nc) rgb[p * 3 + c] = image.pixels[p * nc + source[c]] * scale;
  }
  const bool spread = apply_glare(rgb, image.width, image.height, glare_);
  if (glare_spread) *glare_spread = spread;
  op_->apply(rgb);
  if (gamma_)
    for (float& v : rgb) v = std::pow(std::max(v, 0.0f), 1 / *gamma_);
  else
    display_.apply(rgb, image.width, image.height);
  // Display transforms do not clamp, and a studio config may produce NaN
  // from out-of-range input; neither may reach the quantiser.
  for (float& v : rgb) v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
  return rgb;
}

std::string Developer::describe() const {
  std::string s = op_->describe() + " exposure=" + std::to_string(op_->exposure());
  if (glare_.mode != GlareMode::None) {
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.6g", glare_.degrees_per_pixel);
    s += std::string(" glare=") + glare_mode_name(glare_.mode) + " degrees_per_pixel=" + angle;
  }
  if (gamma_) return s + " gamma=" + std::to_string(*gamma_);
  s += " display=" + display_.display() + " view=" + display_.view();
  if (!display_.look().empty()) s += " look=" + display_.look();
  return s;
}

}  // namespace caustica

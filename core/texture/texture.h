#pragma once

#include <algorithm>
#include <memory>
#include <optional>

#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"
#include "core/math/vec.h"
#include "core/registry/plugin.h"

namespace caustica {

// The smallest and the largest value any channel of a texture takes.
struct ValueRange {
  float lowest = 0, highest = 0;
};

// A colour that varies over a surface's (u, v) parametrisation.
class Texture : public Plugin {
 public:
  virtual Color eval(Vec2 uv) const = 0;
  virtual Color mean() const = 0;
  virtual ValueRange range() const = 0;
  // The spectrum the texture stands for, where it is one given as such
  // (spectral transport reads it in place of eval's colour).
  virtual const SampledSpectrum* spectrum() const { return nullptr; }
  // Width and height in texels, for a texture that has them (an image).
  virtual std::optional<Vec2i> resolution() const { return std::nullopt; }
};

// What an rgb, spectrum or float value stands for where a texture is accepted.
class ConstantTexture final : public Texture {
 public:
  explicit ConstantTexture(Color c, std::shared_ptr<const SampledSpectrum> spectrum = nullptr)
      : c_(c), spectrum_(std::move(spectrum)) {}
  Color eval(Vec2) const override { return c_; }
  Color mean() const override { return c_; }
  ValueRange range() const override { return {std::min({c_.r, c_.g, c_.b}), std::max({c_.r, c_.g, c_.b})}; }
  const SampledSpectrum* spectrum() const override { return spectrum_.get(); }

 private:
  Color c_;
  std::shared_ptr<const SampledSpectrum> spectrum_;
};

}  // namespace caustica

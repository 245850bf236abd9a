#pragma once

#include <memory>

#include "core/texture/texture.h"

namespace caustica {

// A texture times a non-negative factor: Mitsuba 0.x's `scale` texture,
// and how a 0.x material scales its reflectances down to conserve energy.
class ScaledTexture : public Texture {
 public:
  ScaledTexture(std::shared_ptr<Texture> texture, float factor) : texture_(std::move(texture)), factor_(factor) {
    if (const SampledSpectrum* s = texture_->spectrum()) {
      auto scaled = std::make_shared<SampledSpectrum>(*s);
      for (double& v : scaled->values) v *= factor_;
      spectrum_ = std::move(scaled);
    }
  }

  Color eval(Vec2 uv) const override { return texture_->eval(uv) * factor_; }
  Color mean() const override { return texture_->mean() * factor_; }
  ValueRange range() const override {
    const ValueRange r = texture_->range();
    return {r.lowest * factor_, r.highest * factor_};
  }
  const SampledSpectrum* spectrum() const override { return spectrum_.get(); }
  std::optional<Vec2i> resolution() const override { return texture_->resolution(); }

 private:
  std::shared_ptr<Texture> texture_;
  float factor_;
  std::shared_ptr<const SampledSpectrum> spectrum_;
};

}  // namespace caustica

#pragma once

#include <optional>

#include "core/math/color.h"
#include "core/sampling/sampler.h"
#include "core/scene/scene.h"
#include "core/spectral/wavelengths.h"

namespace caustica {

// The wavelengths one sample's paths carry: in spectral mode drawn from the
// sampler's next number, in RGB mode none (and no number is drawn).
class SampleWavelengths {
 public:
  SampleWavelengths(const Scene& scene, Sampler& sampler) {
    if (scene.features().spectral) w_ = sample_wavelengths(sampler.next_1d());
  }
  // A copy of wavelengths a photon round shares (null in RGB mode): each
  // path gets its own, as dispersion terminates a path's secondaries.
  explicit SampleWavelengths(const Wavelengths* shared) {
    if (shared) w_ = *shared;
  }

  // Null in RGB mode.
  Wavelengths* get() { return w_ ? &*w_ : nullptr; }
  // An estimate at them in Rec.709; in RGB mode the estimate itself.
  Color to_rgb(Color c) const { return w_ ? spectral_to_rgb(c, *w_) : c; }

 private:
  std::optional<Wavelengths> w_;
};

}  // namespace caustica

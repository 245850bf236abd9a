#pragma once

#include <string>
#include <vector>

#include "core/color/glare.h"
#include "core/registry/param_spec.h"
#include "core/registry/plugin.h"

namespace caustica {

class Properties;

// Maps scene-linear Rec.709 radiance (already scaled by the exposure) to
// display-linear Rec.709, mostly within [0, 1]; the OpenColorIO view then
// encodes it for the display. Operators see the whole image, since global
// ones (Reinhard's) adapt to its statistics. Non-finite input never gives
// non-finite output.
class ToneOperator : public Plugin {
 public:
  explicit ToneOperator(const Properties& props);

  // In place, on pixel-interleaved RGB.
  virtual void apply(std::vector<float>& rgb) const = 0;
  // Its name and curve parameters; exposure and glare are the developer's to report.
  std::string describe() const;
  // Exposure in stops, applied before the operator (2^exposure).
  float exposure() const { return exposure_; }
  void set_exposure(float ev) { exposure_ = ev; }
  // The glare a scene asks for, spread before the operator (the developer's to apply).
  GlareMode glare() const { return glare_; }

 private:
  float exposure_;
  GlareMode glare_;
};

// The parameters every operator accepts (exposure, glare), for registrations.
std::vector<ParamSpec> tone_operator_params(std::vector<ParamSpec> own);

// Replaces NaN and negative values by 0 and +Inf by the largest float, so
// operators can assume ordinary non-negative numbers.
float sanitize_radiance(float v);

}  // namespace caustica

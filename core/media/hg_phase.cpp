// hg: the Henyey-Greenstein phase function, one lobe whose mean cosine is g
// (g > 0 scatters forward, g < 0 backward, 0 is isotropic):
//   p(theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)),
// theta being the angle between the light's direction before and after.
//
//   <phase type="hg">
//       <float name="g" value="0.7"/>
//   </phase>

#include <cmath>

#include "core/math/constants.h"
#include "core/math/frame.h"
#include "core/media/phase_function.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

float hg_density(float cos_theta, float g) {
  const float denom = 1 + g * g - 2 * g * cos_theta;
  return kInv4Pi * (1 - g * g) / (denom * std::sqrt(denom));
}

class HgPhase final : public PhaseFunction {
 public:
  explicit HgPhase(const Properties& props) : g_(props.get_float("g")) {
    if (!(g_ > -1 && g_ < 1)) throw props.error("g", "must lie strictly between -1 and 1");
  }

  // The light arrives travelling along -wi and leaves along wo.
  float eval(Vec3 wo, Vec3 wi) const override { return hg_density(-dot(wo, wi), g_); }

  std::optional<PhaseSample> sample(Vec3 wo, Vec2 u) const override {
    // The inverse of the density's cumulative distribution over cos theta.
    float cos_theta;
    if (std::abs(g_) < 1e-3f) {
      cos_theta = 1 - 2 * u.x;
    } else {
      const float s = (1 - g_ * g_) / (1 - g_ + 2 * g_ * u.x);
      cos_theta = (1 + g_ * g_ - s * s) / (2 * g_);
    }
    cos_theta = std::clamp(cos_theta, -1.0f, 1.0f);
    const float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
    const float phi = 2 * kPi * u.y;
    // The direction the light leaves in makes angle theta with the one it
    // arrived in; wi points back along the arrival.
    const Frame frame = Frame::from_normal(wo);
    const Vec3 arrival_travel = frame.to_world({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
    const Vec3 wi = -arrival_travel;
    return PhaseSample{wi, hg_density(cos_theta, g_)};
  }

  float mean_cosine() const override { return g_; }

 private:
  float g_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(HgPhase, "phase", "hg",
                         {{"g", ParamType::Float, "0.8",
                           "mean cosine of the scattering angle, in (-1, 1): > 0 forward, < 0 backward"}},
                         {});

}  // namespace caustica

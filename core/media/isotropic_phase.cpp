// isotropic: scattering equally in every direction, p = 1 / (4 pi).
//
//   <phase type="isotropic"/>

#include "core/math/constants.h"
#include "core/media/phase_function.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class IsotropicPhase final : public PhaseFunction {
 public:
  explicit IsotropicPhase(const Properties&) {}

  float eval(Vec3, Vec3) const override { return kInv4Pi; }
  std::optional<PhaseSample> sample(Vec3, Vec2 u) const override {
    return PhaseSample{square_to_uniform_sphere(u), kInv4Pi};
  }
  float mean_cosine() const override { return 0; }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(IsotropicPhase, "phase", "isotropic", {}, {});

}  // namespace caustica

// constant: a uniform environment, radiance arriving equally from every direction.
//
//   <emitter type="constant"><rgb name="radiance" value="0.5"/></emitter>

#include "core/lights/emission_parameter.h"
#include "core/lights/emitter.h"
#include "core/lights/scene_disk.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class ConstantEmitter final : public Emitter {
 public:
  explicit ConstantEmitter(const Properties& props) : radiance_(read_emission(props, "radiance")) {
    set_measured_emission(props.spectrum("radiance"));
  }

  void prepare(const Bounds3& bounds) override { disk_.fit(bounds); }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const override {
    const Vec3 wi = square_to_uniform_sphere(u);
    return LiSample{wi, radiance_, uniform_sphere_pdf(), false, ref.p + wi * disk_.beyond(), {}, {}, true};
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return uniform_sphere_pdf(); }

  Color Le_infinite(Vec3, float) const override { return radiance_; }

  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir, float) const override {
    const Vec3 d = -square_to_uniform_sphere(u_dir);
    return LeSample{{disk_.origin(d, u_pos), d, kInfinity}, {}, radiance_, disk_.pdf(), uniform_sphere_pdf(), {}};
  }

  void pdf_Le(const Ray&, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = disk_.pdf();
    *pdf_dir = uniform_sphere_pdf();
  }

  Color power() const override { return radiance_ * (4 * kPi * disk_.area()); }
  bool is_infinite() const override { return true; }

 private:
  Color radiance_;
  SceneDisk disk_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(ConstantEmitter, "emitter", "constant",
                         {{"radiance", ParamType::Color, "1", "environment radiance"}}, {});

}  // namespace caustica

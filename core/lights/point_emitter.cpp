// point: an isotropic point light.
//
//   <emitter type="point">
//       <point name="position" value="0, 1.9, 0"/>
//       <rgb name="intensity" value="10"/>
//   </emitter>

#include "core/lights/emission_parameter.h"
#include "core/lights/emitter.h"
#include "core/lights/point_light_li.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class PointEmitter final : public Emitter {
 public:
  explicit PointEmitter(const Properties& props)
      : intensity_(read_emission(props, "intensity")),
        position_(props.get_transform("to_world").point(props.get_point("position"))) {
    set_measured_emission(props.spectrum("intensity"));
  }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2) const override {
    return point_light_Li(position_, ref, [&](Vec3) { return intensity_; });
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }

  std::optional<LeSample> sample_Le(Vec2, Vec2 u_dir, float) const override {
    const Vec3 d = square_to_uniform_sphere(u_dir);
    return LeSample{{position_, d, kInfinity}, {}, intensity_, 1, uniform_sphere_pdf(), {}};
  }

  void pdf_Le(const Ray&, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = 1;  // a delta position, reported as sample_Le reports it
    *pdf_dir = uniform_sphere_pdf();
  }

  Color power() const override { return intensity_ * (4 * kPi); }
  std::optional<LightBounds> light_bounds() const override {
    LightBounds b;
    b.bounds.expand(position_);
    b.phi = power().average();
    return b;
  }
  bool is_delta() const override { return true; }

 private:
  Color intensity_;
  Vec3 position_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    PointEmitter, "emitter", "point",
    {{"intensity", ParamType::Color, "1", "radiant intensity, W/sr per channel"},
     {"position", ParamType::Point, "0, 0, 0", "position, before to_world (give this or to_world)"},
     {"to_world", ParamType::Transform, "", "placement: the light sits at to_world applied to position"}},
    {});

}  // namespace caustica

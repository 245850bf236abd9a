// directional: light arriving from one direction everywhere, like the sun
// seen from the ground without its disk (a delta in direction). It gives
// `irradiance` on a surface facing it.
//
//   <emitter type="directional">
//       <vector name="direction" value="0, -1, -1"/>
//       <rgb name="irradiance" value="3"/>
//   </emitter>

#include <cmath>

#include "core/lights/emission_parameter.h"
#include "core/lights/emitter.h"
#include "core/lights/scene_disk.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class DirectionalEmitter final : public Emitter {
 public:
  explicit DirectionalEmitter(const Properties& props) : irradiance_(read_emission(props, "irradiance")) {
    set_measured_emission(props.spectrum("irradiance"));
    if (props.has("direction") && props.has("to_world"))
      throw props.error("direction", "give either direction or to_world, not both");
    const Vec3 d =
        props.has("direction") ? props.get_vector("direction") : props.get_transform("to_world").vector({0, 0, 1});
    const float len = length(d);
    if (!(len > 0) || !std::isfinite(len))
      throw props.error(props.has("direction") ? "direction" : "to_world", "must give a nonzero finite direction");
    direction_ = d / len;
  }

  void prepare(const Bounds3& bounds) override { disk_.fit(bounds); }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2) const override {
    const Vec3 wi = -direction_;
    return LiSample{wi, irradiance_, 1, true, ref.p + wi * disk_.beyond(), {}, {}, true};
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }

  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2, float) const override {
    return LeSample{{disk_.origin(direction_, u_pos), direction_, kInfinity}, {}, irradiance_, disk_.pdf(), 1, {}};
  }

  // The direction is a delta: no other strategy can produce it, so its
  // density is reported as zero outside sample_Le.
  void pdf_Le(const Ray&, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = disk_.pdf();
    *pdf_dir = 0;
  }

  Color power() const override { return irradiance_ * disk_.area(); }
  bool is_delta() const override { return true; }
  bool is_infinite() const override { return true; }

 private:
  Color irradiance_;
  Vec3 direction_;
  SceneDisk disk_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    DirectionalEmitter, "emitter", "directional",
    {{"irradiance", ParamType::Color, "1", "irradiance on a surface facing the light, W/m^2 per channel"},
     {"direction", ParamType::Vector, std::nullopt, "direction the light travels (give this or to_world)"},
     {"to_world", ParamType::Transform, "", "orientation: the light travels along local +z"}},
    {});

}  // namespace caustica

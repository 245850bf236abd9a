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
#include "core/math/constants.h"
#include "core/math/frame.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {

class DirectionalEmitter final : public Emitter {
 public:
  explicit DirectionalEmitter(const Properties& props) : irradiance_(read_emission(props, "irradiance")) {
    if (props.has("direction") && props.has("to_world"))
      throw props.error("direction", "give either direction or to_world, not both");
    const Vec3 d =
        props.has("direction") ? props.get_vector("direction") : props.get_transform("to_world").vector({0, 0, 1});
    const float len = length(d);
    if (!(len > 0) || !std::isfinite(len))
      throw props.error(props.has("direction") ? "direction" : "to_world", "must give a nonzero finite direction");
    direction_ = d / len;
    frame_ = Frame::from_normal(direction_);
  }

  void prepare(const Bounds3& bounds) override {
    if (bounds.empty()) return;
    center_ = bounds.center();
    radius_ = std::max(length(bounds.hi - center_), 1e-3f) * 1.01f;
  }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2) const override {
    const Vec3 wi = -direction_;
    return LiSample{wi, irradiance_, 1, true, ref.p + wi * (2 * radius_), {}, {}, true};
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }

  // Rays start on a disk across the scene's bounding sphere, facing the
  // direction of travel, so that every point of the scene is reached.
  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2) const override {
    const Vec2 disk = square_to_uniform_disk_concentric(u_pos);
    const Vec3 o = center_ - direction_ * radius_ + (frame_.s * disk.x + frame_.t * disk.y) * radius_;
    return LeSample{{o, direction_, kInfinity}, {}, irradiance_, disk_pdf(), 1, false};
  }

  // The direction is a delta: no other strategy can produce it, so its
  // density is reported as zero outside sample_Le.
  void pdf_Le(const Ray&, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = disk_pdf();
    *pdf_dir = 0;
  }

  Color power() const override { return irradiance_ * (kPi * radius_ * radius_); }
  bool is_delta() const override { return true; }
  bool is_infinite() const override { return true; }

 private:
  float disk_pdf() const { return 1 / (kPi * radius_ * radius_); }

  Color irradiance_;
  Vec3 direction_;
  Frame frame_;
  Vec3 center_;
  float radius_ = 1;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    DirectionalEmitter, "emitter", "directional",
    {{"irradiance", ParamType::Color, "1", "irradiance on a surface facing the light, W/m^2 per channel"},
     {"direction", ParamType::Vector, std::nullopt, "direction the light travels (give this or to_world)"},
     {"to_world", ParamType::Transform, "", "orientation: the light travels along local +z"}},
    {});

}  // namespace caustica

// directionalarea: Mitsuba 3's directional area light: the shape it is
// nested in sends light from each point along the point's normal only, a
// parallel beam from a flat shape (a slide projector's condenser, a laser
// sheet). `radiance` is the power per unit area each point sends (W/m^2),
// so the light's power is radiance times the shape's area, and a surface
// the beam meets square on receives it as its irradiance.
//
// No path from the camera or from a surface finds the one direction in
// which a point emits, so only light paths see it: integrators that do not
// trace every light path from the lights refuse the scene (Mitsuba renders
// it with its particle tracer only, for the same reason).
//
//   <shape type="rectangle">
//       <emitter type="directionalarea"><rgb name="radiance" value="5"/></emitter>
//   </shape>

#include "core/geometry/offset.h"
#include "core/lights/shape_emitter.h"
#include "core/shapes/shape.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class DirectionalAreaEmitter final : public ShapeEmitter {
 public:
  using ShapeEmitter::ShapeEmitter;

  bool seen_by_light_paths_only() const override { return true; }

  // A point of the scene lies on one emitting point's normal at most.
  std::optional<LiSample> sample_Li(const ReferencePoint&, Vec2) const override { return std::nullopt; }
  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }

  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2, float) const override {
    const PositionSample ps = shape_->sample_position(u_pos);
    if (ps.pdf <= 0) return std::nullopt;
    const Vec3 d = ps.n;
    // The direction is a delta, taken with density one as the sun's is.
    return LeSample{
        {offset_ray_origin(ps.p, ps.p_error, ps.n, d), d, kInfinity}, ps.n, radiance_->eval(ps.uv), ps.pdf, 1, ps.uv};
  }

  // No other strategy produces the direction: zero, as for the sun.
  void pdf_Le(const Ray&, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = 1 / shape_->area();
    *pdf_dir = 0;
  }

  // Exact for a constant radiance; with a texture, its mean over (u, v)
  // stands for its mean over the surface, as for `area`.
  Color power() const override { return radiance_->mean() * shape_->area(); }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(DirectionalAreaEmitter, "emitter", "directionalarea",
                         {{"radiance", ParamType::Texture, "1",
                           "power per unit area sent along the shape's normal, W/m^2 per channel"}},
                         {});

}  // namespace caustica

// area: makes the shape it is nested in emit diffusely from the side its
// normals point to (the geometric normal, turned to the side of the shading
// normal where a mesh has vertex normals), uniformly or with a radiance
// texture over the shape's (u, v).
//
//   <shape type="rectangle">
//       <emitter type="area"><rgb name="radiance" value="18, 14, 6.7"/></emitter>
//   </shape>

#include "core/lights/shape_emitter.h"
#include "core/math/constants.h"
#include "core/sampling/warp.h"
#include "core/shapes/shape.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class AreaEmitter final : public ShapeEmitter {
 public:
  using ShapeEmitter::ShapeEmitter;

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const override {
    const PositionSample ps = shape_->sample_seen_from(ref.p, u);
    if (ps.pdf <= 0) return std::nullopt;
    const Vec3 wi = normalize(ps.p - ref.p);
    // Emission is one-sided: a point seen from behind sends nothing.
    if (dot(wi, ps.n) >= 0) return std::nullopt;
    return LiSample{wi, radiance_->eval(ps.uv), ps.pdf, false, ps.p, ps.p_error, ps.n, false};
  }

  float pdf_Li(const ReferencePoint& ref, Vec3 wi, const SurfaceInteraction& on_light) const override {
    if (dot(wi, on_light.ng) >= 0) return 0;
    return shape_->pdf_seen_from(ref.p, on_light);
  }

  Color L(const SurfaceInteraction& si, Vec3 w) const override {
    return dot(w, si.ng) > 0 ? radiance_->eval(si.uv) : Color();
  }

  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir, float) const override {
    const PositionSample ps = shape_->sample_position(u_pos);
    if (ps.pdf <= 0) return std::nullopt;
    const Vec3 local = square_to_cosine_hemisphere(u_dir);
    const float pdf_dir = cosine_hemisphere_pdf(local.z);
    if (pdf_dir <= 0) return std::nullopt;
    const Vec3 d = Frame::from_normal(ps.n).to_world(local);
    return LeSample{{offset_ray_origin(ps.p, ps.p_error, ps.n, d), d, kInfinity},
                    ps.n,
                    radiance_->eval(ps.uv),
                    ps.pdf,
                    pdf_dir,
                    ps.uv};
  }

  void pdf_Le(const Ray& ray, Vec3 n, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = 1 / shape_->area();
    *pdf_dir = cosine_hemisphere_pdf(dot(ray.d, n));
  }

  // Exact for a constant radiance; with a texture, its mean over (u, v)
  // stands for its mean over the surface (light selection needs only a
  // positive weight for each light, not the exact power).
  Color power() const override { return radiance_->mean() * (kPi * shape_->area()); }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(AreaEmitter, "emitter", "area",
                         {{"radiance", ParamType::Texture, "1", "emitted radiance (a colour or a texture)"}}, {});

}  // namespace caustica

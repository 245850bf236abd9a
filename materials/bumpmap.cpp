// bumpmap: fine relief from a height texture, by tilting the shading normal.
//
// The displaced surface is p + n scale h(u, v); its tangents are
// dp/du + n scale dh/du and dp/dv + n scale dh/dv (the tangents first made
// perpendicular to n), and their cross product, oriented to the side of n,
// is the perturbed normal n'. The nested BSDF sees directions in the frame
// around n' whose first axis follows dp/du. dh/du and dh/dv are central
// differences over 1/1024 of the unit uv square.
//
// Directions on the same side of the shading surface but on opposite sides
// of the perturbed one (and the converse) carry nothing, so no light leaks
// through the relief; the nested BSDF's cosine is taken about n', so the
// result is not reciprocal in general and can lose energy at grazing angles.
//
// The nested texture is the height field h (its luminance is used), the
// nested bsdf the material evaluated in the perturbed frame. scale times h
// is a height in the surface's own units per unit of u and v, as dp/du and
// dp/dv measure them.
//
//   <bsdf type="bumpmap">
//       <texture type="bitmap">
//           <string name="filename" value="bumps.png"/>
//           <boolean name="raw" value="true"/>
//       </texture>
//       <float name="scale" value="0.01"/>
//       <bsdf type="diffuse"/>
//   </bsdf>

#include <cmath>

#include "core/bsdf/perturbed_frame_bsdf.h"
#include "core/registry/properties.h"
#include "core/texture/texture.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr float kStep = 1.0f / 1024;

class BumpMapBsdf final : public PerturbedFrameBsdf {
 public:
  explicit BumpMapBsdf(const Properties& props)
      : PerturbedFrameBsdf(props), height_(props.child<Texture>("texture")), scale_(props.get_float("scale")) {
    if (!height_) throw SceneError(props.where(), "bsdf 'bumpmap' takes one nested height texture");
    if (!std::isfinite(scale_)) throw props.error("scale", "must be a finite number");
  }

 private:
  float height(Vec2 uv) const { return height_->eval(uv).luminance(); }

  Frame frame(const BsdfContext& ctx) const override {
    const float dh_du = (height({ctx.uv.x + kStep, ctx.uv.y}) - height({ctx.uv.x - kStep, ctx.uv.y})) / (2 * kStep);
    const float dh_dv = (height({ctx.uv.x, ctx.uv.y + kStep}) - height({ctx.uv.x, ctx.uv.y - kStep})) / (2 * kStep);
    const Vec3 tu(ctx.dpdu.x, ctx.dpdu.y, scale_ * dh_du);
    const Vec3 tv(ctx.dpdv.x, ctx.dpdv.y, scale_ * dh_dv);
    Vec3 n = cross(tu, tv);
    const float len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return Frame::from_normal_and_tangent({0, 0, 1}, ctx.dpdu);
    n = n / len;
    if (n.z < 0) n = -n;
    return Frame::from_normal_and_tangent(n, tu);
  }

  std::shared_ptr<Texture> height_;
  float scale_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(BumpMapBsdf, "bsdf", "bumpmap",
                         {{"scale", ParamType::Float, "1", "multiplies the height (the texture's luminance)"}},
                         {"texture", "bsdf"});

}  // namespace caustica

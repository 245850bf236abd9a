// normalmap: shading normals read from a tangent-space normal map.
//
// Parameters
//   normalmap  texture  (required)  RGB normal map; load a bitmap with
//                                   raw="true" so its values stay as stored
//   (nested)   bsdf                 the material evaluated in the perturbed frame
//
// A colour c decodes to the normal 2 c - 1 in the tangent frame (s, t, n):
// s along dp/du (made perpendicular to the shading normal n), t = n x s. So
// (0.5, 0.5, 1) leaves the surface as it is, and red tilts the normal toward
// +u. The nested BSDF sees directions in the frame around the decoded normal
// n' whose first axis follows dp/du. Colours decoding to a normal at or
// below the surface (or to none) leave the normal unperturbed.
//
// Directions on the same side of the shading surface but on opposite sides
// of the perturbed one (and the converse) carry nothing, so no light leaks;
// the nested BSDF's cosine is taken about n', so the result is not
// reciprocal in general and can lose energy at grazing angles.
//
//   <bsdf type="normalmap">
//       <texture type="bitmap" name="normalmap">
//           <string name="filename" value="normals.png"/>
//           <boolean name="raw" value="true"/>
//       </texture>
//       <bsdf type="diffuse"/>
//   </bsdf>

#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {

class NormalMapBsdf final : public Bsdf {
 public:
  explicit NormalMapBsdf(const Properties& props)
      : normals_(props.get_texture("normalmap")), nested_(props.child<Bsdf>("bsdf")) {
    if (!nested_) throw SceneError(props.where(), "bsdf 'normalmap' takes one nested bsdf");
  }

  uint32_t lobes() const override { return nested_->lobes(); }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const Frame f = frame(ctx);
    const Vec3 wo_p = f.to_local(wo), wi_p = f.to_local(wi);
    if (!sides_agree(wo, wi, wo_p, wi_p)) return {};
    return nested_->eval(nested_context(ctx, f), wo_p, wi_p);
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const Frame f = frame(ctx);
    const Vec3 wo_p = f.to_local(wo), wi_p = f.to_local(wi);
    if (!sides_agree(wo, wi, wo_p, wi_p)) return 0;
    return nested_->pdf(nested_context(ctx, f), wo_p, wi_p);
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    const Frame f = frame(ctx);
    const Vec3 wo_p = f.to_local(wo);
    auto s = nested_->sample(nested_context(ctx, f), wo_p, u_lobe, u);
    if (!s) return std::nullopt;
    const Vec3 wi = f.to_world(s->wi);
    if (!sides_agree(wo, wi, wo_p, s->wi)) return std::nullopt;
    s->wi = wi;
    return s;
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const Frame f = frame(ctx);
    return nested_->albedo(nested_context(ctx, f), f.to_local(wo));
  }

 private:
  // Reflection or transmission must mean the same about both surfaces.
  static bool sides_agree(Vec3 wo, Vec3 wi, Vec3 wo_p, Vec3 wi_p) {
    return wo.z * wo_p.z > 0 && wi.z * wi_p.z > 0 && same_hemisphere(wo, wi) == same_hemisphere(wo_p, wi_p);
  }

  // The perturbed shading frame, in the local frame of the unperturbed one.
  Frame frame(const BsdfContext& ctx) const {
    const Frame tangent = Frame::from_normal_and_tangent({0, 0, 1}, ctx.dpdu);
    const Color c = normals_->eval(ctx.uv);
    const Vec3 m(2 * c.r - 1, 2 * c.g - 1, 2 * c.b - 1);
    const float len = length(m);
    if (!(len > 0) || !std::isfinite(len) || !(m.z > 1e-4f * len)) return tangent;
    return Frame::from_normal_and_tangent(tangent.to_world(m / len), ctx.dpdu);
  }

  static BsdfContext nested_context(const BsdfContext& ctx, const Frame& f) {
    BsdfContext out = ctx;
    out.dpdu = f.to_local(ctx.dpdu);
    out.dpdv = f.to_local(ctx.dpdv);
    return out;
  }

  std::shared_ptr<Texture> normals_;
  std::shared_ptr<Bsdf> nested_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(NormalMapBsdf, "bsdf", "normalmap",
                         {{"normalmap", ParamType::Texture, std::nullopt, "tangent-space normal map"}}, {"bsdf"});

}  // namespace caustica

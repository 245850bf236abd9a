// normalmap: shading normals read from a tangent-space normal map.
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

#include "core/bsdf/perturbed_frame_bsdf.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class NormalMapBsdf final : public PerturbedFrameBsdf {
 public:
  explicit NormalMapBsdf(const Properties& props)
      : PerturbedFrameBsdf(props), normals_(read_texture(props, "normalmap")) {}

 private:
  Frame frame(const BsdfContext& ctx) const override {
    const Frame tangent = Frame::from_normal_and_tangent({0, 0, 1}, ctx.dpdu);
    const Color c = normals_->eval(ctx.uv);
    const Vec3 m(2 * c.r - 1, 2 * c.g - 1, 2 * c.b - 1);
    const float len = length(m);
    if (!(len > 0) || !std::isfinite(len) || !(m.z > 1e-4f * len)) return tangent;
    return Frame::from_normal_and_tangent(tangent.to_world(m / len), ctx.dpdu);
  }

  std::shared_ptr<Texture> normals_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(NormalMapBsdf, "bsdf", "normalmap",
                         {{"normalmap", ParamType::Texture, std::nullopt,
                           "tangent-space RGB normal map; load a bitmap with raw=true so its values stay as stored"}},
                         {"bsdf"});

}  // namespace caustica

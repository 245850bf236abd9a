// null: no surface at all, only a boundary. Light passes through unchanged,
// so a shape made of it is invisible except as the border of the media it
// bounds (an index-matched boundary). A shape that bounds media and has no
// material gets this one.
//
//   <shape type="sphere">
//       <bsdf type="null"/>
//       <ref name="interior" id="smoke"/>
//   </shape>

#include "core/bsdf/bsdf.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class NullBsdf final : public Bsdf {
 public:
  explicit NullBsdf(const Properties&) {}

  uint32_t lobes() const override { return kNull; }
  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }
  // The walk steps through null surfaces without asking them anything; a
  // path that does ask finds nothing to scatter.
  Color eval(const BsdfContext&, Vec3, Vec3) const override { return {}; }
  float pdf(const BsdfContext&, Vec3, Vec3) const override { return 0; }
  std::optional<BsdfSample> sample(const BsdfContext&, Vec3, float, Vec2) const override { return std::nullopt; }
  Color albedo(const BsdfContext&, Vec3) const override { return {}; }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(NullBsdf, "bsdf", "null", {}, {});

}  // namespace caustica

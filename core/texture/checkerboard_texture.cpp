// checkerboard: a procedural two-colour check pattern.
//
// The unit square holds 2 x 2 checks and the pattern repeats outside it. As
// in Mitsuba 3, a point is in color0 when frac(u) > 0.5 and frac(v) > 0.5
// agree (both true or both false), i.e. floor(2u) + floor(2v) is even away
// from the check borders; a coordinate of exactly 0.5 belongs to the lower
// half. mean() is the average of the two colours' means.
//
//   <texture type="checkerboard" name="reflectance">
//       <rgb name="color0" value="0.8"/>
//       <rgb name="color1" value="0.1"/>
//       <transform name="to_uv">
//           <scale x="4" y="4"/>
//       </transform>
//   </texture>

#include <cmath>
#include <optional>

#include "core/math/transform.h"
#include "core/registry/properties.h"
#include "core/texture/texture.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class CheckerboardTexture final : public Texture {
 public:
  explicit CheckerboardTexture(const Properties& props)
      : color0_(read_texture(props, "color0")), color1_(read_texture(props, "color1")) {
    if (props.has("to_uv")) to_uv_ = props.get_transform("to_uv");
  }

  // Nested colour textures see the surface's own uv, not the transformed one.
  Color eval(Vec2 uv) const override {
    Vec2 st = uv;
    if (to_uv_) {
      const Vec3 p = to_uv_->point({uv.x, uv.y, 0});
      st = {p.x, p.y};
    }
    const bool upper_u = st.x - std::floor(st.x) > 0.5f;
    const bool upper_v = st.y - std::floor(st.y) > 0.5f;
    return upper_u == upper_v ? color0_->eval(uv) : color1_->eval(uv);
  }

  Color mean() const override { return (color0_->mean() + color1_->mean()) * 0.5f; }
  ValueRange range() const override {
    const ValueRange a = color0_->range(), b = color1_->range();
    return {std::min(a.lowest, b.lowest), std::max(a.highest, b.highest)};
  }

 private:
  std::shared_ptr<Texture> color0_, color1_;
  std::optional<Transform> to_uv_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    CheckerboardTexture, "texture", "checkerboard",
    {{"color0", ParamType::Texture, "0.4", "colour of the checks containing (0, 0) and (0.5, 0.5)"},
     {"color1", ParamType::Texture, "0.2", "colour of the other two checks"},
     {"to_uv", ParamType::Transform, std::nullopt, "applied to (u, v, 0) before the lookup (optional)"}},
    {});

}  // namespace caustica

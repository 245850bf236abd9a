// scale: a nested texture times a factor (Mitsuba 0.x), e.g. to set the
// strength of a bump map's height texture.
//
//   <texture type="scale">
//       <float name="scale" value="0.3"/>
//       <texture type="bitmap"><string name="filename" value="bumps.png"/></texture>
//   </texture>

#include <cmath>

#include "core/registry/properties.h"
#include "core/texture/scaled_texture.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

float factor_of(const Properties& props) {
  const float factor = props.get_float("scale");
  if (!(factor >= 0) || !std::isfinite(factor)) throw props.error("scale", "must be a finite number of 0 or more");
  return factor;
}

std::shared_ptr<Texture> nested_of(const Properties& props) {
  auto nested = props.child<Texture>("texture");
  if (!nested) throw SceneError(props.where(), "a scale texture needs a nested <texture> to scale");
  return nested;
}

class ScaleTexture final : public ScaledTexture {
 public:
  explicit ScaleTexture(const Properties& props) : ScaledTexture(nested_of(props), factor_of(props)) {}
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(ScaleTexture, "texture", "scale",
                         {{"scale", ParamType::Float, "1", "the factor the nested texture is multiplied by"}},
                         {"texture"});

}  // namespace caustica

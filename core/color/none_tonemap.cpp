// none: no tone curve; display values are the scene values clipped to [0, 1].
//
//   <tonemap type="none"><float name="exposure" value="1"/></tonemap>

#include <algorithm>

#include "core/color/tone_operator.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class NoneTonemap final : public ToneOperator {
 public:
  explicit NoneTonemap(const Properties& props) : ToneOperator(props) {}

  void apply(std::vector<float>& rgb) const override {
    for (float& v : rgb) v = std::min(sanitize_radiance(v), 1.0f);
  }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(NoneTonemap, "tonemap", "none", tone_operator_params({}), {});

}  // namespace caustica

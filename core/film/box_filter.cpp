// box: every sample inside the pixel counts equally.
//
//   <rfilter type="box"/>

#include "core/film/reconstruction_filter.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class BoxFilter final : public ReconstructionFilter {
 public:
  explicit BoxFilter(const Properties& props) {
    const float r = props.get_float("radius");
    if (!(r > 0)) throw props.error("radius", "must be positive");
    init(r);
  }
  float eval(float x) const override { return std::abs(x) <= radius() ? 1.0f : 0.0f; }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(BoxFilter, "rfilter", "box", {{"radius", ParamType::Float, "0.5", "half-width in pixels"}},
                         {});

}  // namespace caustica

// tent: the triangle filter max(0, 1 - |x| / radius) along each axis.
//
//   <rfilter type="tent"/>

#include <algorithm>
#include <cmath>

#include "core/film/reconstruction_filter.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class TentFilter final : public ReconstructionFilter {
 public:
  explicit TentFilter(const Properties& props) {
    const float r = props.get_float("radius");
    if (!(r > 0)) throw props.error("radius", "must be positive");
    init(r);
  }
  float eval(float x) const override { return std::max(0.0f, 1 - std::abs(x) / radius()); }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(TentFilter, "rfilter", "tent", {{"radius", ParamType::Float, "1", "half-width in pixels"}},
                         {});

}  // namespace caustica

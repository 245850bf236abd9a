// gaussian: exp(-x^2 / (2 stddev^2)) along each axis, cut off at 4 stddev.
//
//   <rfilter type="gaussian"><float name="stddev" value="0.5"/></rfilter>

#include <cmath>

#include "core/film/reconstruction_filter.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class GaussianFilter final : public ReconstructionFilter {
 public:
  explicit GaussianFilter(const Properties& props) : stddev_(props.get_float("stddev")) {
    if (!(stddev_ > 0)) throw props.error("stddev", "must be positive");
    init(4 * stddev_);
  }
  float eval(float x) const override {
    return std::abs(x) <= radius() ? std::exp(-x * x / (2 * stddev_ * stddev_)) : 0.0f;
  }

 private:
  float stddev_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(GaussianFilter, "rfilter", "gaussian",
                         {{"stddev", ParamType::Float, "0.5", "standard deviation in pixels"}}, {});

}  // namespace caustica

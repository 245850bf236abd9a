#include "core/color/tone_operator.h"

#include <cmath>
#include <limits>

#include "core/registry/properties.h"

namespace caustica {

ToneOperator::ToneOperator(const Properties& props) : exposure_(props.get_float("exposure")) {}

std::vector<ParamSpec> tone_operator_params(std::vector<ParamSpec> own) {
  own.push_back({"exposure", ParamType::Float, "0", "exposure in stops, applied first"});
  return own;
}

float sanitize_radiance(float v) {
  if (!(v > 0)) return 0;  // NaN, zero and negative
  return std::isinf(v) ? std::numeric_limits<float>::max() : v;
}

}  // namespace caustica

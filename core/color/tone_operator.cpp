#include "core/color/tone_operator.h"

#include <cmath>
#include <limits>

#include "core/registry/properties.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

GlareMode glare_parameter(const Properties& props) {
  try {
    return parse_glare_mode(props.get_string("glare"));
  } catch (const std::invalid_argument&) {
    throw props.error("glare", "must be none, whole or clipped");
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

ToneOperator::ToneOperator(const Properties& props)
    : exposure_(props.get_float("exposure")), glare_(glare_parameter(props)) {}

std::string ToneOperator::describe() const {
  std::string s = plugin_name();
  for (const auto& [param, value] : parameters())
    if (param != "exposure" && param != "glare") s += " " + param + "=" + value;
  return s;
}

std::vector<ParamSpec> tone_operator_params(std::vector<ParamSpec> own) {
  own.push_back({"exposure", ParamType::Float, "0", "exposure in stops, applied first"});
  own.push_back({"glare", ParamType::String, "none",
                 "the eye's glare, spread after the exposure: none, whole (every pixel) or clipped (what exceeds 1)"});
  return own;
}

float sanitize_radiance(float v) {
  if (!(v > 0)) return 0;  // NaN, zero and negative
  return std::isinf(v) ? std::numeric_limits<float>::max() : v;
}

}  // namespace caustica

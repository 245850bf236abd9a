#include "core/bsdf/ior.h"

#include <cmath>
#include <utility>

#include "core/registry/properties.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Published refractive indices (sodium D line, room temperature).
const std::pair<const char*, float> kIors[] = {
    {"vacuum", 1.0f},      {"helium", 1.00004f},         {"hydrogen", 1.00013f},
    {"air", 1.00028f},     {"carbon dioxide", 1.00045f}, {"water", 1.3330f},
    {"acetone", 1.36f},    {"ethanol", 1.361f},          {"carbon tetrachloride", 1.461f},
    {"glycerol", 1.4729f}, {"benzene", 1.501f},          {"silicone oil", 1.52045f},
    {"bromine", 1.661f},   {"water ice", 1.31f},         {"fused quartz", 1.458f},
    {"pyrex", 1.470f},     {"acrylic glass", 1.49f},     {"polypropylene", 1.49f},
    {"bk7", 1.5046f},      {"sodium chloride", 1.544f},  {"amber", 1.55f},
    {"pet", 1.575f},       {"diamond", 2.419f}};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::optional<float> named_ior(const std::string& name) {
  for (const auto& [n, v] : kIors)
    if (name == n) return v;
  return std::nullopt;
}

std::vector<std::string> ior_names() {
  std::vector<std::string> out;
  for (const auto& [n, v] : kIors) out.push_back(n);
  return out;
}

float read_ior(const Properties& props, const std::string& name) {
  const PropertyValue v = props.value(name, ParamType::Ior);
  float ior = 0;
  if (v.kind == ValueKind::String) {
    const std::string& text = std::get<std::string>(v.value);
    if (const auto known = named_ior(text)) {
      ior = *known;
    } else {
      // Defaults are written as text, so a default of "1.5" arrives here too.
      try {
        ior = float(std::get<double>(parse_value_text(ValueKind::Float, text, v.where).value));
      } catch (const SceneError&) {
        throw props.error(name, "unknown index of refraction '" + text + "' (known: " + join_names(ior_names()) + ")");
      }
    }
  } else {
    ior = v.kind == ValueKind::Integer ? float(std::get<int64_t>(v.value)) : float(std::get<double>(v.value));
  }
  // As in Mitsuba, any positive index: an interface whose inside is the
  // less dense medium (air in ice) has int_ior below ext_ior, or below 1.
  if (!(ior > 0 && std::isfinite(ior))) throw props.error(name, "an index of refraction must be positive");
  return ior;
}

}  // namespace caustica

#include "core/bsdf/ior.h"

#include <utility>

namespace caustica {

namespace {

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

}  // namespace caustica

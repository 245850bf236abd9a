#pragma once

#include <optional>
#include <string>
#include <vector>

namespace caustica {

// Indices of refraction of common materials by name (Mitsuba's names), at
// about 589 nm.
std::optional<float> named_ior(const std::string& name);
std::vector<std::string> ior_names();

}  // namespace caustica

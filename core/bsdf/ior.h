#pragma once

#include <optional>
#include <string>
#include <vector>

namespace caustica {

class Properties;

// Indices of refraction of common materials by name (Mitsuba's names), at
// about 589 nm.
std::optional<float> named_ior(const std::string& name);
std::vector<std::string> ior_names();

// A parameter declared as an index of refraction: a number, or a name from
// the table above; at least 1.
float read_ior(const Properties& props, const std::string& name);

}  // namespace caustica

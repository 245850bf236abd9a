#pragma once

#include <optional>
#include <string>

namespace caustica {

// Ior: an index of refraction, a number or a material name such as "bk7".
// Medium: a nested or referenced <medium>; it has no default.
// Volume: a nested <volume>, or a number or colour the same everywhere.
enum class ParamType { Boolean, Integer, Float, String, Color, Texture, Point, Vector, Transform, Ior, Medium, Volume };

const char* to_string(ParamType t);

// A parameter a plugin accepts. The default is written as in a scene file
// ("0.5", "1, 0, 0", "true") and parsed the same way; no default means the
// parameter is required.
struct ParamSpec {
  std::string name;
  ParamType type;
  std::optional<std::string> default_value;
  std::string doc;
};

}  // namespace caustica

#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "core/math/color.h"

namespace caustica::test {

// Writes a w x h RGB EXR whose texel (x, y) is value(x, y) to the temporary
// directory under `name`, for envmap emitters; returns its path.
std::filesystem::path write_env_map(const std::string& name, const std::function<Color(int, int)>& value, int w, int h);

}  // namespace caustica::test

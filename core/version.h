#pragma once

namespace caustica {

inline constexpr const char* kVersion = "0.1.0";

}  // namespace caustica

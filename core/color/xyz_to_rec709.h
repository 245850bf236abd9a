#pragma once

#include <array>

namespace caustica {

// CIE XYZ to linear Rec.709 (sRGB primaries, D65 white), IEC 61966-2-1.
inline constexpr double kXyzToRec709[3][3] = {
    {3.2404542, -1.5371385, -0.4985314}, {-0.9692660, 1.8760108, 0.0415560}, {0.0556434, -0.2040259, 1.0572252}};

inline std::array<double, 3> xyz_to_rec709(const std::array<double, 3>& xyz) {
  std::array<double, 3> rgb{};
  for (int r = 0; r < 3; ++r)
    rgb[size_t(r)] = kXyzToRec709[r][0] * xyz[0] + kXyzToRec709[r][1] * xyz[1] + kXyzToRec709[r][2] * xyz[2];
  return rgb;
}

}  // namespace caustica

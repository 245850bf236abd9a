#pragma once

#include <array>

namespace caustica {

// The CIE's tables every 5 nm from kCieFirstNm to kCieLastNm.
inline constexpr int kCieFirstNm = 360, kCieLastNm = 830, kCieStepNm = 5;
inline constexpr int kCieSamples = (kCieLastNm - kCieFirstNm) / kCieStepNm + 1;

// CIE 1931 2-degree colour matching functions x, y, z.
extern const std::array<double, kCieSamples> kCieX, kCieY, kCieZ;
// CIE standard illuminant D65, relative (1 at 560 nm).
extern const std::array<double, kCieSamples> kCieD65;

}  // namespace caustica

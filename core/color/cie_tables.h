#pragma once

#include <array>
#include <cstddef>

namespace caustica {

// The CIE's tables every 5 nm from kCieFirstNm to kCieLastNm.
inline constexpr int kCieFirstNm = 360, kCieLastNm = 830, kCieStepNm = 5;
inline constexpr int kCieSamples = (kCieLastNm - kCieFirstNm) / kCieStepNm + 1;

// CIE 1931 2-degree colour matching functions x, y, z.
extern const std::array<double, kCieSamples> kCieX, kCieY, kCieZ;
// CIE standard illuminant D65, relative (1 at 560 nm).
extern const std::array<double, kCieSamples> kCieD65;

// A table's value at `nm`, linear between its 5 nm samples, 0 outside.
inline double cie_table_at(const std::array<double, kCieSamples>& table, double nm) {
  const double x = (nm - kCieFirstNm) / kCieStepNm;
  if (x < 0 || x > kCieSamples - 1) return 0;
  const int i = x < kCieSamples - 2 ? int(x) : kCieSamples - 2;
  const double t = x - i;
  return table[std::size_t(i)] * (1 - t) + table[std::size_t(i) + 1] * t;
}

}  // namespace caustica

#include "core/render/pass_time.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/pcg32.h"

namespace caustica {

float pass_time(uint64_t pass, uint64_t seed) {
  uint64_t reversed = 0;
  for (int bit = 0; bit < 64; ++bit) reversed |= ((pass >> bit) & 1u) << (63 - bit);
  const double radical_inverse = double(reversed >> 11) * 0x1p-53;
  const double shift = double(mix_bits(seed ^ 0x74696d65ull) >> 11) * 0x1p-53;
  const double u = std::fmod(radical_inverse + shift, 1.0);
  return float(std::min(u, 0x1.fffffep-1));
}

}  // namespace caustica

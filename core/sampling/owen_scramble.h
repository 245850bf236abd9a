#pragma once

#include <cstdint>

namespace caustica {

constexpr uint32_t reverse_bits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// A nested uniform (Owen) scramble of the binary digits of a fraction held
// bit-reversed (its first digit in bit 0), by hashing (Burley 2020, after
// Laine and Karras 2011): every digit is flipped or not by a hash of the
// digits before it, which are the lower bits, and adding a seed or xoring
// in a product with an even number carries only from lower bits to higher
// ones. A bijection on 32-bit words; applied to a bit-reversed sequence
// index it maps every aligned block of 2^m indices onto an aligned block of
// 2^m.
constexpr uint32_t owen_scramble_reversed(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// The first two dimensions of Sobol's sequence at index i, as 32-bit
// fractions held bit-reversed (ready for owen_scramble_reversed): van der
// Corput's radical inverse, which reversed is i itself, and the dimension
// of the primitive polynomial x + 1, whose direction numbers are v_1 = 1/2,
// v_{k+1} = v_k xor v_k / 2. Together a (0, 2)-sequence in base 2: every
// aligned block of 2^m points has one point in each elementary interval of
// area 2^-m.
constexpr uint32_t sobol_first_reversed(uint32_t i) { return i; }

namespace detail {
// Xors of the reversed direction numbers, one table per byte of the index.
struct SobolSecondTables {
  uint32_t byte[4][256] = {};
};
constexpr SobolSecondTables make_sobol_second_tables() {
  uint32_t reversed[32] = {};
  for (uint32_t k = 0, v = 0x80000000u; k < 32; ++k, v ^= v >> 1) reversed[k] = reverse_bits(v);
  SobolSecondTables t;
  for (int b = 0; b < 4; ++b)
    for (uint32_t value = 0; value < 256; ++value)
      for (int k = 0; k < 8; ++k)
        if (value >> k & 1) t.byte[b][value] ^= reversed[8 * b + k];
  return t;
}
inline constexpr SobolSecondTables kSobolSecond = make_sobol_second_tables();
}  // namespace detail

constexpr uint32_t sobol_second_reversed(uint32_t i) {
  const auto& t = detail::kSobolSecond.byte;
  return t[0][i & 0xff] ^ t[1][i >> 8 & 0xff] ^ t[2][i >> 16 & 0xff] ^ t[3][i >> 24];
}

}  // namespace caustica

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

// A nested uniform (Owen) scramble of x's binary digits, x read as the
// fraction x / 2^32, by hashing (Burley 2020, after Laine and Karras 2011):
// every digit is flipped or not by a hash of the digits before it. Bit
// reversed, the digits before are the lower bits, and adding a seed or
// xoring in a product with an even number carries only from lower bits to
// higher ones. A bijection on 32-bit words; applied to a sequence index it
// maps every aligned block of 2^m indices onto an aligned block of 2^m.
constexpr uint32_t owen_scramble(uint32_t x, uint32_t seed) {
  x = reverse_bits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverse_bits(x);
}

// The first two dimensions of Sobol's sequence at index i, as 32-bit
// fractions: van der Corput's radical inverse, and the dimension of the
// primitive polynomial x + 1, whose direction numbers are v_1 = 1/2,
// v_{k+1} = v_k xor v_k / 2. Together a (0, 2)-sequence in base 2: every
// aligned block of 2^m points has one point in each elementary interval of
// area 2^-m.
constexpr uint32_t sobol_first(uint32_t i) { return reverse_bits(i); }

constexpr uint32_t sobol_second(uint32_t i) {
  uint32_t v = 0x80000000u, out = 0;
  for (; i != 0; i >>= 1, v ^= v >> 1)
    if (i & 1) out ^= v;
  return out;
}

}  // namespace caustica

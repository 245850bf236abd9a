#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include "core/sampling/pcg32.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The hashes the stratifying samplers derive their scrambles from: one for
// a sample's (stream, key, seed, block of indices), then one per dimension
// drawn from it.
inline uint64_t sample_hash(SampleKey key, uint64_t seed, uint64_t block) {
  return mix_bits(mix_bits(key.key ^ mix_bits(uint64_t(key.stream) * 0xd1b54a32d192ed03ULL)) ^ mix_bits(seed) ^
                  mix_bits(block + 0x9e3779b97f4a7c15ULL));
}

namespace detail {
constexpr uint64_t dimension_key(uint64_t dimension) { return mix_bits(dimension * 0x9e3779b97f4a7c15ULL); }
// The keys of the dimensions a path reaches, known at compile time: one
// hash less on every draw's chain of dependent multiplications.
constexpr size_t kTabledDimensions = 256;
struct DimensionKeys {
  uint64_t key[kTabledDimensions] = {};
};
constexpr DimensionKeys make_dimension_keys() {
  DimensionKeys t;
  for (size_t d = 0; d < kTabledDimensions; ++d) t.key[d] = dimension_key(d);
  return t;
}
inline constexpr DimensionKeys kDimensionKeys = make_dimension_keys();
}  // namespace detail

inline uint64_t dimension_hash(uint64_t sample, uint64_t dimension) {
  return mix_bits(sample ^ (dimension < detail::kTabledDimensions ? detail::kDimensionKeys.key[dimension]
                                                                  : detail::dimension_key(dimension)));
}

// A bijection on [0, n) chosen by `seed`: an invertible hash of the low
// half on the smallest power of two holding n, walked along its cycle
// until it lands below n, then rotated by an offset from the high half.
// The rotation sends every i to each of [0, n) equally often over seeds: a
// cycle walk alone favours some images when n is not a power of two, which
// biases a stratified estimate and correlates neighbouring pixels' samples.
inline uint32_t hashed_permutation(uint32_t i, uint32_t n, uint64_t seed64) {
  const uint32_t seed = uint32_t(seed64);
  uint32_t mask = n - 1;
  for (int s = 1; s < 32; s *= 2) mask |= mask >> s;
  const int half = (std::bit_width(mask) + 1) / 2;
  do {
    i = (i ^ seed) & mask;
    i = (i * 0x9e3779b1u + (seed >> 16)) & mask;
    i ^= i >> half;
    i = (i * 0x85ebca77u) & mask;
    i ^= i >> half;
  } while (i >= n);
  i += uint32_t(((seed64 >> 32) * n) >> 32);
  return i >= n ? i - n : i;
}

// A uniform float in [0, 1) from a hash's top 24 bits.
inline float unit_from_hash(uint64_t h) { return float(h >> 40) * 0x1p-24f; }

}  // namespace caustica

#pragma once

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

inline uint64_t dimension_hash(uint64_t sample, uint64_t dimension) {
  return mix_bits(sample ^ mix_bits(dimension * 0x9e3779b97f4a7c15ULL));
}

}  // namespace caustica

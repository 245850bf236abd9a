#include "core/sampling/jittered_block_sampler.h"

#include <algorithm>

#include "core/math/constants.h"
#include "core/registry/properties.h"

namespace caustica {

JitteredBlockSampler::JitteredBlockSampler(const Properties& props, BlockGrid grid)
    : Sampler(read_block_sample_count(props)),
      seed_(props.get_int("seed")),
      jitter_(props.get_bool("jitter")),
      grid_(grid),
      block_size_(grid.columns * grid.rows) {}

uint32_t JitteredBlockSampler::read_block_sample_count(const Properties& props) {
  const int64_t n = props.get_int("sample_count");
  if (n <= 0 || n > (int64_t(1) << 30)) throw props.error("sample_count", "must be between 1 and 2^30");
  return uint32_t(n);
}

void JitteredBlockSampler::start_sample(SampleKey key, uint64_t sample_index, uint64_t seed) {
  base_ = sample_hash(key, seed + uint64_t(seed_), sample_index / block_size_);
  within_ = uint32_t(sample_index % block_size_);
  dimension_ = 0;
}

float JitteredBlockSampler::next_1d() {
  const uint64_t h = next_dimension_hash();
  return std::min((float(permuted_index(h)) + jitter(h, 0)) / float(block_size_), kOneMinusEpsilon);
}

float JitteredBlockSampler::jitter(uint64_t h, uint64_t axis) const {
  return jitter_ ? unit_from_hash(mix_bits(h ^ mix_bits((uint64_t(within_) << 2 | axis) + 0x632be59bd9b4e019ULL)))
                 : 0.5f;
}

}  // namespace caustica

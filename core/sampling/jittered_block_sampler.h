#pragma once

#include <cstdint>

#include "core/sampling/sample_hash.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The grid of a block: its 2-D pairs put one point in each cell.
struct BlockGrid {
  uint32_t columns, rows;
};

// What the stratified and multijitter samplers share. A pixel's samples
// come in blocks of n = columns x rows (sample_count rounded up to the grid
// the sampler fills);
// each dimension of a block draws its own permutation of the block and its
// own jitter from (seed, stream, key, block, dimension), and every 1-D
// dimension puts one sample in each of n strata. Renders of more samples
// than sample_count continue block by block; a render that stops inside a
// block is unbiased but less stratified.
class JitteredBlockSampler : public Sampler {
 public:
  JitteredBlockSampler(const Properties& props, BlockGrid grid);

  void start_sample(SampleKey key, uint64_t sample_index, uint64_t seed) override;
  float next_1d() override;

  // sample_count with a lower bound than other samplers': the block it
  // rounds up to must fit 32 bits.
  static uint32_t read_block_sample_count(const Properties& props);

 protected:
  const BlockGrid& grid() const { return grid_; }
  uint64_t next_dimension_hash() { return dimension_hash(base_, ++dimension_); }
  // The sample's place in the block under the dimension's permutation.
  uint32_t permuted_index(uint64_t h) const { return hashed_permutation(within_, block_size_, h); }
  // The position within a stratum along `axis`: uniform, or its centre
  // without jitter.
  float jitter(uint64_t h, uint64_t axis) const;

 private:
  int64_t seed_;
  bool jitter_;
  BlockGrid grid_;
  uint32_t block_size_, within_ = 0;
  uint64_t base_ = 0, dimension_ = 0;
};

}  // namespace caustica

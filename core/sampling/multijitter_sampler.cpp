// multijitter: correlated multi-jittered samples (Kensler 2013). A pixel's
// samples come in blocks of n = a * b (sample_count rounded up to a grid of
// a columns and b rows, a = ceil(sqrt(sample_count))). Within a block every
// 2-D pair puts one sample in each cell of the a x b grid and, along each
// axis, one in each of the n strata of width 1/n (n-rooks); every 1-D
// dimension puts one sample in each of n strata. Each dimension permutes
// the block and its columns and rows by hashes of its own
// (jittered_block_sampler.h).
//
//   <sampler type="multijitter"><integer name="sample_count" value="16"/></sampler>

#include <algorithm>
#include <cmath>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/jittered_block_sampler.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

BlockGrid near_square_grid(const Properties& props) {
  const uint32_t n = JitteredBlockSampler::read_block_sample_count(props);
  const uint32_t columns = uint32_t(std::ceil(std::sqrt(double(n))));
  return {columns, (n + columns - 1) / columns};
}

class MultijitterSampler final : public JitteredBlockSampler {
 public:
  explicit MultijitterSampler(const Properties& props) : JitteredBlockSampler(props, near_square_grid(props)) {}
  MultijitterSampler(const MultijitterSampler&) = default;

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<MultijitterSampler>(*this); }

  // The permuted index s names a cell: column s % a (shuffled alike in
  // every row) and row s / a. Within the cell a shuffle of the row picks
  // the sub-column and a shuffle of the column the sub-row, so that each
  // of the n strata of width 1/n along x and along y is hit once. The
  // sub-row is not the column itself (as in Kensler's paper): that would
  // tie y's finest strata to x's coarse ones, and a point would no longer
  // be uniform in the square.
  Vec2 next_2d() override {
    const uint64_t h = next_dimension_hash(), h2 = mix_bits(h), h3 = mix_bits(h2), h4 = mix_bits(h3);
    const uint32_t s = permuted_index(h);
    const uint32_t a = grid().columns, b = grid().rows;
    const uint32_t column = hashed_permutation(s % a, a, h2), row = s / a;
    const uint32_t sub_column = hashed_permutation(row, b, h3);
    const uint32_t sub_row = hashed_permutation(column, a, h4);
    const float x = (float(column) + (float(sub_column) + jitter(h, 1)) / float(b)) / float(a);
    const float y = (float(row) + (float(sub_row) + jitter(h, 2)) / float(a)) / float(b);
    return {std::min(x, kOneMinusEpsilon), std::min(y, kOneMinusEpsilon)};
  }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(MultijitterSampler, "sampler", "multijitter",
                         {{"sample_count", ParamType::Integer, "4",
                           "samples per pixel, rounded up to a grid of ceil(sqrt(n)) columns; the size of a block"},
                          {"seed", ParamType::Integer, "0", "random seed; offsets every permutation and jitter"},
                          {"jitter", ParamType::Boolean, "true", "jitter samples within their strata"}},
                         {});

}  // namespace caustica

// stratified: jittered stratified samples. A pixel's samples come in blocks
// of n = k^2 (sample_count rounded up to a square): within a block every
// 1-D dimension puts one sample in each of n strata, and every 2-D pair one
// in each cell of a k x k grid, each dimension visiting its strata in an
// order of its own (jittered_block_sampler.h).
//
//   <sampler type="stratified"><integer name="sample_count" value="16"/></sampler>

#include <algorithm>
#include <cmath>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/jittered_block_sampler.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

BlockGrid square_grid(const Properties& props) {
  const auto side = uint32_t(std::ceil(std::sqrt(double(JitteredBlockSampler::read_block_sample_count(props)))));
  return {side, side};
}

class StratifiedSampler final : public JitteredBlockSampler {
 public:
  explicit StratifiedSampler(const Properties& props) : JitteredBlockSampler(props, square_grid(props)) {}
  StratifiedSampler(const StratifiedSampler&) = default;

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }

  Vec2 next_2d() override {
    const uint64_t h = next_dimension_hash();
    const uint32_t cell = permuted_index(h), side = grid().columns;
    return {std::min((float(cell % side) + jitter(h, 1)) / float(side), kOneMinusEpsilon),
            std::min((float(cell / side) + jitter(h, 2)) / float(side), kOneMinusEpsilon)};
  }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(StratifiedSampler, "sampler", "stratified",
                         {{"sample_count", ParamType::Integer, "4",
                           "samples per pixel, rounded up to a square; the size of a stratified block"},
                          {"seed", ParamType::Integer, "0", "random seed; offsets every permutation and jitter"},
                          {"jitter", ParamType::Boolean, "true", "jitter samples within their strata"}},
                         {});

}  // namespace caustica

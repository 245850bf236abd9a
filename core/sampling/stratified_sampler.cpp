// stratified: jittered stratified samples. A pixel's samples come in blocks
// of n = k^2 (sample_count rounded up to a square): within a block every
// 1-D dimension puts one sample in each of n strata, and every 2-D pair one
// in each cell of a k x k grid, each dimension visiting its strata in an
// order of its own (a hashed permutation per seed, stream, key, block and
// dimension) and jittered within them. Values stay a pure function of
// (seed, stream, key, sample index, dimension). Renders of more samples than
// sample_count continue block by block; a render that stops inside a block
// is unbiased but less stratified.
//
//   <sampler type="stratified"><integer name="sample_count" value="16"/></sampler>

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/sample_hash.h"

namespace caustica {
namespace {

// A bijection on [0, n) chosen by `seed`: an invertible hash on the
// smallest power of two holding n, walked along its cycle until it lands
// below n.
uint32_t permute(uint32_t i, uint32_t n, uint32_t seed) {
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
  return i;
}

float unit(uint64_t h) { return float(h >> 40) * 0x1p-24f; }

class StratifiedSampler final : public Sampler {
 public:
  explicit StratifiedSampler(const Properties& props)
      : Sampler(block_size(props)), seed_(props.get_int("seed")), jitter_(props.get_bool("jitter")) {}
  StratifiedSampler(const StratifiedSampler&) = default;

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }

  void start_sample(SampleKey key, uint64_t sample_index, uint64_t seed) override {
    side_ = uint32_t(std::ceil(std::sqrt(double(sample_count()))));
    const uint64_t n = uint64_t(side_) * side_;
    base_ = sample_hash(key, seed + uint64_t(seed_), sample_index / n);
    within_ = uint32_t(sample_index % n);
    dimension_ = 0;
  }

  float next_1d() override {
    const uint64_t h = dimension_hash(base_, ++dimension_);
    const uint32_t n = side_ * side_;
    return std::min((float(permute(within_, n, uint32_t(h))) + jitter(h, 0)) / float(n), kOneMinusEpsilon);
  }

  Vec2 next_2d() override {
    const uint64_t h = dimension_hash(base_, ++dimension_);
    const uint32_t cell = permute(within_, side_ * side_, uint32_t(h));
    return {std::min((float(cell % side_) + jitter(h, 1)) / float(side_), kOneMinusEpsilon),
            std::min((float(cell / side_) + jitter(h, 2)) / float(side_), kOneMinusEpsilon)};
  }

 private:
  // sample_count with a lower bound than other samplers': its square
  // rounded up must fit 32 bits.
  static uint32_t block_size(const Properties& props) {
    const int64_t n = props.get_int("sample_count");
    if (n <= 0 || n > (int64_t(1) << 30)) throw props.error("sample_count", "must be between 1 and 2^30");
    return uint32_t(n);
  }

  // The position within a stratum: uniform, or its centre without jitter.
  float jitter(uint64_t h, uint64_t axis) const {
    return jitter_ ? unit(mix_bits(h ^ mix_bits((uint64_t(within_) << 2 | axis) + 0x632be59bd9b4e019ULL))) : 0.5f;
  }

  int64_t seed_;
  bool jitter_;
  uint32_t side_ = 1, within_ = 0;
  uint64_t base_ = 0, dimension_ = 0;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(StratifiedSampler, "sampler", "stratified",
                         {{"sample_count", ParamType::Integer, "4",
                           "samples per pixel, rounded up to a square; the size of a stratified block"},
                          {"seed", ParamType::Integer, "0", "random seed; offsets every permutation and jitter"},
                          {"jitter", ParamType::Boolean, "true", "jitter samples within their strata"}},
                         {});

}  // namespace caustica

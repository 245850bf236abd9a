// ldsampler: low-discrepancy samples, each pair of dimensions an
// Owen-scrambled (0, 2)-sequence (Sobol's first two dimensions), so that the
// samples of a pixel stratify every 2-D projection a path uses (the film
// position, the lens, each light and BSDF sample) at every power of two.
// Each dimension or pair draws its own scrambles and its own shuffle of the
// sample index from (seed, stream, key, dimension): pairs stay uncorrelated
// with one another and with neighbouring pixels, and a value remains a pure
// function of (seed, stream, key, sample index, dimension), as DESIGN asks
// of every sampler. Stratification is best for sample counts and ranges of
// powers of two; any count stays unbiased.
//
//   <sampler type="ldsampler"><integer name="sample_count" value="64"/></sampler>

#include "core/registry/properties.h"
#include "core/sampling/owen_scramble.h"
#include "core/sampling/sample_hash.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A 32-bit fraction to a float in [0, 1), exactly representable.
float to_unit(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

class LowDiscrepancySampler final : public Sampler {
 public:
  explicit LowDiscrepancySampler(const Properties& props)
      : Sampler(read_sample_count(props)), seed_(props.get_int("seed")) {}
  LowDiscrepancySampler(const LowDiscrepancySampler&) = default;

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<LowDiscrepancySampler>(*this); }

  void start_sample(SampleKey key, uint64_t sample_index, uint64_t seed) override {
    // Indices past 2^32 continue in a sequence scrambled apart.
    base_ = sample_hash(key, seed + uint64_t(seed_), sample_index >> 32);
    reversed_index_ = reverse_bits(uint32_t(sample_index));
    dimension_ = 0;
  }

  // The index shuffled, then each coordinate scrambled; everything stays
  // bit-reversed until the value is read.
  float next_1d() override {
    const uint64_t h = dimension_hash(base_, ++dimension_);
    const uint32_t i = reverse_bits(owen_scramble_reversed(reversed_index_, uint32_t(h)));
    return to_unit(reverse_bits(owen_scramble_reversed(sobol_first_reversed(i), uint32_t(h >> 32))));
  }

  Vec2 next_2d() override {
    const uint64_t h = dimension_hash(base_, ++dimension_), h2 = mix_bits(h);
    const uint32_t i = reverse_bits(owen_scramble_reversed(reversed_index_, uint32_t(h)));
    return {to_unit(reverse_bits(owen_scramble_reversed(sobol_first_reversed(i), uint32_t(h >> 32)))),
            to_unit(reverse_bits(owen_scramble_reversed(sobol_second_reversed(i), uint32_t(h2))))};
  }

 private:
  int64_t seed_;
  uint64_t base_ = 0, dimension_ = 0;
  uint32_t reversed_index_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(LowDiscrepancySampler, "sampler", "ldsampler",
                         {{"sample_count", ParamType::Integer, "4", "samples per pixel; powers of two stratify best"},
                          {"seed", ParamType::Integer, "0", "random seed; offsets every scramble"}},
                         {});

}  // namespace caustica

// independent: uniform random numbers from PCG32, keyed by (seed, stream,
// key, sample index) and skipped ahead to the sample, so every sample can be
// reproduced on its own.
//
//   <sampler type="independent"><integer name="sample_count" value="64"/></sampler>

#include "core/registry/properties.h"
#include "core/sampling/pcg32.h"
#include "core/sampling/sampler.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Dimensions one sample may consume before it would run into the next
// sample's stream; far beyond any path's needs.
constexpr Pcg32::Stride kDimensionsPerSample(uint64_t(1) << 20);

class IndependentSampler final : public Sampler {
 public:
  explicit IndependentSampler(const Properties& props)
      : Sampler(read_sample_count(props)), seed_(props.get_int("seed")) {}
  IndependentSampler(const IndependentSampler&) = default;

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }

  void start_sample(SampleKey key, uint64_t sample_index, uint64_t seed) override {
    // Camera pixels keep the key as it is; other streams are hashed apart from them.
    const uint64_t k = key.stream == SampleStream::CameraPixel
                           ? key.key
                           : mix_bits(key.key ^ mix_bits(uint64_t(key.stream) * 0xd1b54a32d192ed03ULL));
    rng_.seed(mix_bits(k ^ mix_bits(seed + uint64_t(seed_))), mix_bits(k + 0x9e3779b97f4a7c15ULL));
    rng_.advance(sample_index, kDimensionsPerSample);
  }

  float next_1d() override { return rng_.next_float(); }
  Vec2 next_2d() override {
    const float a = rng_.next_float();
    return {a, rng_.next_float()};
  }

 private:
  int64_t seed_;
  Pcg32 rng_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(IndependentSampler, "sampler", "independent",
                         {{"sample_count", ParamType::Integer, "4", "samples per pixel"},
                          {"seed", ParamType::Integer, "0", "random seed; offsets every random number"}},
                         {});

}  // namespace caustica

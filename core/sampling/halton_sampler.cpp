// halton: the Halton sequence, Owen-scrambled per pixel. Dimension d is
// the radical inverse of the sample index in the d-th prime base (2, 3, 5,
// ...; past the 1024th prime the bases repeat under scrambles of their
// own), so a 2-D pair takes two consecutive primes. Every digit is permuted
// by a hash of (seed, stream, key, dimension) and the digits before it, a
// nested scramble that leaves each value uniform on its own and keeps the
// sequence's strata. A permutation, not a shift: under a shift the first
// few samples of two large consecutive primes stay on a line (i/p, i/q),
// and the render's error at 64 spp is worse than independent samples'. The
// strata: the first sample_count samples of a pixel put one value
// in each interval of width b^-k for every b^k <= sample_count, and one
// point in each box of 2^-i x 3^-j for 2^i 3^j <= sample_count in the
// first pair. Digits past those sample_count resolves are one uniform draw,
// which is what the nested scramble makes of them.
//
//   <sampler type="halton"><integer name="sample_count" value="64"/></sampler>

#include <algorithm>
#include <array>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/sample_hash.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kPrimeCount = 1024;

// A prime base with its 64-bit reciprocal, for division of 32-bit numbers
// by multiplication (Lemire, Kaser and Kurz 2019): the digit loop would
// otherwise spend most of its time dividing.
struct Base {
  uint32_t prime;
  uint64_t reciprocal;

  uint32_t quotient(uint32_t n) const { return uint32_t((unsigned __int128)reciprocal * n >> 64); }
  uint32_t remainder(uint32_t n) const { return uint32_t((unsigned __int128)(reciprocal * n) * prime >> 64); }
};

// By a sieve, which stays within clang's constexpr step limit where trial
// division does not; the 1024th prime is 8161.
constexpr std::array<Base, kPrimeCount> first_primes() {
  constexpr uint32_t kLimit = 8192;
  std::array<bool, kLimit> composite{};
  std::array<Base, kPrimeCount> bases{};
  int found = 0;
  for (uint32_t n = 2; n < kLimit && found < kPrimeCount; ++n) {
    if (composite[n]) continue;
    bases[found++] = {n, ~uint64_t(0) / n + 1};
    for (uint32_t multiple = n * n; multiple < kLimit; multiple += n) composite[multiple] = true;
  }
  return bases;
}

constexpr std::array<Base, kPrimeCount> kBases = first_primes();
static_assert(kBases[kPrimeCount - 1].prime == 8161);

// The radical inverse of `index` in `base`, its digits resolved until
// base^k reaches `resolved`, each permuted by a hash of `h` and the digits
// before it. The permutations are affine, a -> (m a + c) mod p with m in
// [1, p) and c in [0, p): bijections since p is prime, and over hashes
// every digit goes to every value, every pair of digits to every pair,
// equally often.
float scrambled_radical_inverse(uint32_t index, Base base, uint64_t resolved, uint64_t h) {
  const uint32_t p = base.prime;
  uint64_t digits = 0, scale = 1;
  for (; scale < resolved; scale *= p) {
    const uint32_t digit = base.remainder(index);
    index = base.quotient(index);
    const uint32_t m = 1 + uint32_t((uint64_t(uint32_t(h)) * (p - 1)) >> 32);
    const uint32_t c = uint32_t(((h >> 32) * p) >> 32);
    digits = digits * p + base.remainder(m * digit + c);
    h = mix_bits(h ^ ((uint64_t(digit) + 1) * 0x9e3779b97f4a7c15ULL));
  }
  const double tail = unit_from_hash(mix_bits(h ^ (uint64_t(index) + 0x2545f4914f6cdd1dULL)));
  return std::min(float((double(digits) + tail) / double(scale)), kOneMinusEpsilon);
}

class HaltonSampler final : public Sampler {
 public:
  explicit HaltonSampler(const Properties& props) : Sampler(read_sample_count(props)), seed_(props.get_int("seed")) {}
  HaltonSampler(const HaltonSampler&) = default;

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<HaltonSampler>(*this); }

  void start_sample(SampleKey key, uint64_t sample_index, uint64_t seed) override {
    // Indices past 2^32 continue in a sequence scrambled apart.
    base_ = sample_hash(key, seed + uint64_t(seed_), sample_index >> 32);
    index_ = uint32_t(sample_index);
    dimension_ = 0;
  }

  float next_1d() override { return next_dimension(); }

  Vec2 next_2d() override {
    const float x = next_dimension();
    return {x, next_dimension()};
  }

 private:
  float next_dimension() {
    const uint64_t d = dimension_++;
    return scrambled_radical_inverse(index_, kBases[d % kPrimeCount], sample_count(), dimension_hash(base_, d + 1));
  }

  int64_t seed_;
  uint64_t base_ = 0, dimension_ = 0;
  uint32_t index_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(HaltonSampler, "sampler", "halton",
                         {{"sample_count", ParamType::Integer, "4",
                           "samples per pixel; the first sample_count of a pixel are stratified"},
                          {"seed", ParamType::Integer, "0", "random seed; offsets every scramble"}},
                         {});

}  // namespace caustica

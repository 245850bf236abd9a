#pragma once

#include <array>
#include <bit>
#include <cstdint>

#include "core/math/constants.h"

namespace caustica {

// O'Neill's PCG32 (XSH-RR output, 64-bit LCG state), with the logarithmic
// skip-ahead that makes a sample's random numbers a pure function of where
// they sit in the stream.
class Pcg32 {
 public:
  Pcg32() { seed(0x853c49e6748fea9bULL, 0xda3e39cb94b95bdbULL); }
  Pcg32(uint64_t state, uint64_t stream) { seed(state, stream); }

  void seed(uint64_t init_state, uint64_t stream) {
    state_ = 0;
    inc_ = (stream << 1u) | 1u;
    next_u32();
    state_ += init_state;
    next_u32();
  }

  uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * kStep.mult + inc_;
    const auto xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }

  // Uniform in [0, 1): the top 24 bits, so every value is exactly representable.
  float next_float() { return float(next_u32() >> 8) * 0x1p-24f; }

  // Steps of the generator as one affine map of the state:
  // state -> mult * state + plus_per_inc * inc (all modulo 2^64).
  struct Jump {
    uint64_t mult, plus_per_inc;
  };
  static constexpr Jump kStep{0x5851f42d4c957f2dULL, 1};

  // A stride of `steps` steps, with its map raised to every power of two
  // once: a jump of `count` strides then composes only the maps of count's
  // set bits (maps of one stride commute, so their order does not matter).
  class Stride {
   public:
    explicit constexpr Stride(uint64_t steps) {
      Jump j = repeated(kStep, steps);
      for (Jump& power : powers_) {
        power = j;
        j = then(j, j);
      }
    }
    constexpr Jump power_of_two(int k) const { return powers_[size_t(k)]; }

   private:
    std::array<Jump, 64> powers_{};
  };

  // Jumps `delta` steps ahead in O(log delta) (Brown, "Random number
  // generation with arbitrary strides", 1994).
  void advance(uint64_t delta) { apply(repeated(kStep, delta)); }
  // Jumps `count` times `stride` ahead, in as many steps as count has set bits.
  void advance(uint64_t count, const Stride& stride) {
    Jump total{1, 0};
    for (; count != 0; count &= count - 1) total = then(total, stride.power_of_two(std::countr_zero(count)));
    apply(total);
  }

 private:
  // `a`, then `b`.
  static constexpr Jump then(Jump a, Jump b) { return {a.mult * b.mult, a.plus_per_inc * b.mult + b.plus_per_inc}; }
  // `j` applied `count` times, by squaring.
  static constexpr Jump repeated(Jump j, uint64_t count) {
    Jump total{1, 0};
    for (; count > 0; count /= 2, j = then(j, j))
      if (count & 1) total = then(total, j);
    return total;
  }
  void apply(Jump j) { state_ = j.mult * state_ + j.plus_per_inc * inc_; }

  uint64_t state_ = 0, inc_ = 0;
};

// 64-bit finaliser of MurmurHash3: spreads similar keys across the whole range.
constexpr uint64_t mix_bits(uint64_t v) {
  v ^= v >> 33;
  v *= 0xff51afd7ed558ccdULL;
  v ^= v >> 33;
  v *= 0xc4ceb9fe1a85ec53ULL;
  v ^= v >> 33;
  return v;
}

}  // namespace caustica

#pragma once

#include <atomic>
#include <cmath>
#include <cstdint>

namespace caustica {

// A sum of non-negative numbers that comes out the same, bit for bit,
// whatever the order of its additions and however many threads made them:
// each term is rounded once to a 128-bit fixed-point number (64 bits on
// either side of the point), and integer addition is associative. The two
// halves are separate atomics, so the sum may be read only once every
// addition has returned; each carry is added exactly once, so the value
// read then is exact.
class FixedPointSum {
 public:
  // Terms of 2^63 and more are clamped there; below 2^-64 they add nothing.
  void add(double x) {
    if (!(x > 0)) return;
    x = std::fmin(x, 0x1p63);
    const double whole = std::floor(x);
    const auto hi = uint64_t(whole);
    const auto lo = uint64_t((x - whole) * 0x1p64);
    const uint64_t before = lo_.fetch_add(lo, std::memory_order_relaxed);
    const uint64_t carry = before + lo < before ? 1 : 0;
    if (hi + carry) hi_.fetch_add(hi + carry, std::memory_order_relaxed);
  }
  double value() const {
    return double(hi_.load(std::memory_order_relaxed)) + double(lo_.load(std::memory_order_relaxed)) * 0x1p-64;
  }

 private:
  std::atomic<uint64_t> lo_{0}, hi_{0};
};

}  // namespace caustica

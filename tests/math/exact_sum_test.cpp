#include "core/math/exact_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kFinestBit = -20;  // every term is a multiple of 2^kFinestBit

// Terms k * 2^e with 53-bit k and e from kFinestBit to 10: up to 2^73 in
// all, 93 bits above the finest, so the sums fit the pair exactly and their
// exact value fits a 128-bit integer counting units of 2^kFinestBit.
std::vector<double> terms(std::mt19937_64& rng, size_t n) {
  std::uniform_int_distribution<int64_t> mantissa(-(int64_t(1) << 53) + 1, (int64_t(1) << 53) - 1);
  std::uniform_int_distribution<int> exponent(kFinestBit, 10);
  std::vector<double> out;
  for (size_t i = 0; i < n; ++i) out.push_back(std::ldexp(double(mantissa(rng)), exponent(rng)));
  return out;
}

__int128 units(double x) { return __int128(std::ldexp(x, -kFinestBit)); }

ExactSum sum_of(const std::vector<double>& xs) {
  ExactSum s;
  for (double x : xs) s.add(x);
  return s;
}

void expect_same_bits(const ExactSum& a, const ExactSum& b) {
  EXPECT_EQ(std::bit_cast<uint64_t>(a.value()), std::bit_cast<uint64_t>(b.value()));
  EXPECT_EQ(std::bit_cast<uint64_t>(a.rest()), std::bit_cast<uint64_t>(b.rest()));
}

// The oracle is integer arithmetic: value() is the exact sum rounded to a
// double (within half its last place) and rest() the exact remainder.
TEST(ExactSum, HoldsTheExactSumOfItsTerms) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<double> xs = terms(rng, 1 + trial * 5);
    __int128 exact = 0;
    for (double x : xs) exact += units(x);
    const ExactSum s = sum_of(xs);
    const __int128 remainder = exact - units(s.value());
    const double half_ulp = std::ldexp(std::nextafter(std::abs(s.value()), INFINITY) - std::abs(s.value()), -1);
    EXPECT_LE(std::abs(double(remainder)), std::ldexp(half_ulp, -kFinestBit)) << trial;
    EXPECT_EQ(units(s.rest()), remainder) << trial;
  }
}

// Terms that cancel the running sum but for a little: the sum left is
// exact and small, while the rest still holds what earlier terms left over.
TEST(ExactSum, HoldsTheExactSumThroughCancellations) {
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int64_t> little(-(int64_t(1) << 20), int64_t(1) << 20);
  std::uniform_int_distribution<int> exponent(kFinestBit, kFinestBit + 30);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<double> xs = terms(rng, 1 + size_t(trial % 20));
    ExactSum s = sum_of(xs);
    __int128 exact = 0;
    for (double x : xs) exact += units(x);
    for (int step = 0; step < 40; ++step) {
      const double x = -s.value() + std::ldexp(double(little(rng)), exponent(rng));
      s.add(x);
      exact += units(x);
      const __int128 remainder = exact - units(s.value());
      const double half_ulp = std::ldexp(std::nextafter(std::abs(s.value()), INFINITY) - std::abs(s.value()), -1);
      ASSERT_LE(std::abs(double(remainder)), std::ldexp(half_ulp, -kFinestBit)) << trial << " " << step;
      ASSERT_EQ(units(s.rest()), remainder) << trial << " " << step;
    }
  }
}

TEST(ExactSum, KeepsWhatAPlainDoubleLoses) {
  ExactSum s;
  for (double x : {1e16, 1.0, -1e16}) s.add(x);
  EXPECT_EQ(s.value(), 1.0);
  EXPECT_EQ(s.rest(), 0.0);
  EXPECT_EQ(1e16 + 1.0 - 1e16, 0.0);  // what the plain sum gives
}

// The same terms in any order, and summed in groups whose sums are then
// added, give the same bits: what makes renders of disjoint sample ranges,
// or on several machines, merge into the very image of one render.
TEST(ExactSum, AnyOrderAndGroupingGivesTheSameBits) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> xs = terms(rng, 300);
    const ExactSum in_order = sum_of(xs);
    std::shuffle(xs.begin(), xs.end(), rng);
    expect_same_bits(sum_of(xs), in_order);
    ExactSum grouped;
    for (size_t begin = 0; begin < xs.size();) {
      const size_t end = std::min(xs.size(), begin + 1 + size_t(rng() % 40));
      grouped.add(sum_of({xs.begin() + long(begin), xs.begin() + long(end)}));
      begin = end;
    }
    expect_same_bits(grouped, in_order);
    expect_same_bits(ExactSum::from_parts(in_order.value(), in_order.rest()), in_order);
  }
}

TEST(ExactSum, ZeroHasOneBitPattern) {
  ExactSum cancelled;
  for (double x : {0.1, 1e-30, -0.1, -1e-30}) cancelled.add(x);
  ExactSum negative_zero;
  negative_zero.add(-0.0);
  for (const ExactSum& s : {cancelled, negative_zero, ExactSum{}}) expect_same_bits(s, ExactSum{});
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

// Float4's operations give Vec3's results bit for bit, on vectors whose
// components spread over many exponents and both signs: the triangle hit
// points built with them must not move.

#include "core/math/float4.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

void expect_same_bits(Vec3 expected, Float4 actual) {
  for (int i = 0; i < 3; ++i) EXPECT_EQ(std::bit_cast<uint32_t>(expected[i]), std::bit_cast<uint32_t>(actual[i])) << i;
}

void expect_same_bits(float expected, float actual) {
  EXPECT_EQ(std::bit_cast<uint32_t>(expected), std::bit_cast<uint32_t>(actual)) << expected << " " << actual;
}

TEST(Float4, AgreesWithVec3BitForBit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-20, 20);
  const auto component = [&] { return std::ldexp(mantissa(rng), exponent(rng)); };
  const auto vector = [&] { return Vec3(component(), component(), component()); };
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a = vector(), b = vector();
    const float s = component();
    const Float4 fa = to_float4(a), fb = to_float4(b);
    expect_same_bits(a, to_float4(to_vec3(fa)));
    expect_same_bits(abs(a), abs(fa));
    expect_same_bits(max(a, b), max(fa, fb));
    expect_same_bits(max_component(a), max_component(fa));
    expect_same_bits(dot(a, b), dot(fa, fb));
    expect_same_bits(cross(a, b), cross(fa, fb));
    expect_same_bits(normalize(a), normalize(fa));
    expect_same_bits(a * s + b, fa * s + fb);
    expect_same_bits(a - b, fa - fb);
    expect_same_bits((a - b) / s, (fa - fb) / s);
    if (HasFailure()) return;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

#pragma once

#include <limits>

namespace caustica {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Half an ulp of 1: the unit roundoff of IEEE single precision.
inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;
// The largest float below one, so that a sample never reaches 1.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// Bound on the relative error of n chained floating-point operations
// (Higham's gamma_n), used for conservative error bounds on hit points.
constexpr float gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

}  // namespace caustica

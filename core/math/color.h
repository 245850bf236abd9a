#pragma once

#include <algorithm>
#include <cmath>

namespace caustica {

// Linear Rec.709 RGB radiance, reflectance or importance.
struct Color {
  float r = 0, g = 0, b = 0;
  constexpr Color() = default;
  constexpr explicit Color(float v) : r(v), g(v), b(v) {}
  constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr Color operator+(Color o) const { return {r + o.r, g + o.g, b + o.b}; }
  constexpr Color operator-(Color o) const { return {r - o.r, g - o.g, b - o.b}; }
  constexpr Color operator*(Color o) const { return {r * o.r, g * o.g, b * o.b}; }
  constexpr Color operator*(float s) const { return {r * s, g * s, b * s}; }
  constexpr Color operator/(float s) const { return {r / s, g / s, b / s}; }
  constexpr Color& operator+=(Color o) { return *this = *this + o; }
  constexpr Color& operator*=(Color o) { return *this = *this * o; }
  constexpr Color& operator*=(float s) { return *this = *this * s; }
  constexpr bool operator==(const Color&) const = default;
  constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
  float max_component() const { return std::max({r, g, b}); }
  constexpr float average() const { return (r + g + b) / 3; }
  // Rec.709 luminance weights.
  constexpr float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
  bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
  Color clamp(float lo, float hi) const {
    return {std::clamp(r, lo, hi), std::clamp(g, lo, hi), std::clamp(b, lo, hi)};
  }
};

constexpr Color operator*(float s, Color c) { return c * s; }

}  // namespace caustica

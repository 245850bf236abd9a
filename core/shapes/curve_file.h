#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math/vec.h"

namespace caustica {

// Curves as Mitsuba's linearcurve and bsplinecurve read them: one control
// point per line, "x y z radius", and a blank line between curves.
struct CurveData {
  struct ControlPoint {
    Vec3 p;
    float radius;
  };
  std::vector<ControlPoint> points;
  std::vector<uint32_t> first;  // each curve's first point
};

// Reads `text` (the file's bytes); each curve needs at least
// `min_points` control points. Throws MeshFormatError naming the line and
// what is wrong: a line that is not four numbers, a coordinate or radius
// that is not finite, a negative radius, a curve too short, no curve.
CurveData read_curves(const std::string& text, size_t min_points);

}  // namespace caustica

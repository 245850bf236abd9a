#include "core/shapes/curve_file.h"

#include <cmath>
#include <cstdlib>

#include "core/shapes/mesh_format_error.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

[[noreturn]] void fail(size_t line, const std::string& problem) {
  throw MeshFormatError("line " + std::to_string(line) + ": " + problem);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CurveData read_curves(const std::string& text, size_t min_points) {
  CurveData curves;
  size_t line = 0, curve_line = 0;
  bool in_curve = false;
  const auto end_curve = [&] {
    if (in_curve && curves.points.size() - curves.first.back() < min_points)
      fail(curve_line, "a curve of " + std::to_string(curves.points.size() - curves.first.back()) +
                           " control points; it needs at least " + std::to_string(min_points));
    in_curve = false;
  };
  size_t at = 0;
  while (at < text.size()) {
    size_t next = text.find('\n', at);
    if (next == std::string::npos) next = text.size();
    const std::string row = text.substr(at, next - at);
    at = next + 1;
    ++line;
    if (row.find_first_not_of(" \t\r") == std::string::npos) {
      end_curve();
      continue;
    }
    float values[4];
    const char* cursor = row.c_str();
    for (float& v : values) {
      char* after = nullptr;
      v = std::strtof(cursor, &after);
      if (after == cursor) fail(line, "expected four numbers (x y z radius), read '" + row + "'");
      cursor = after;
    }
    if (std::string(cursor).find_first_not_of(" \t\r") != std::string::npos)
      fail(line, "expected four numbers (x y z radius), read '" + row + "'");
    for (float v : values)
      if (!std::isfinite(v)) fail(line, "a control point that is not finite: '" + row + "'");
    if (values[3] < 0) fail(line, "a negative radius: '" + row + "'");
    if (!in_curve) {
      curves.first.push_back(uint32_t(curves.points.size()));
      curve_line = line;
      in_curve = true;
    }
    curves.points.push_back({{values[0], values[1], values[2]}, values[3]});
  }
  end_curve();
  if (curves.points.empty()) throw MeshFormatError("no control points");
  return curves;
}

}  // namespace caustica

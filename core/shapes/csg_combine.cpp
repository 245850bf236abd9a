#include "core/shapes/csg_combine.h"

#include <algorithm>
#include <limits>

namespace caustica {

bool parse_csg_operation(const std::string& name, CsgOperation& out) {
  if (name == "union") {
    out = CsgOperation::Union;
  } else if (name == "intersection") {
    out = CsgOperation::Intersection;
  } else if (name == "difference") {
    out = CsgOperation::Difference;
  } else {
    return false;
  }
  return true;
}

namespace {
namespace CAUSTICA_UNITY_ID {

bool inside(CsgOperation op, const std::vector<char>& in) {
  switch (op) {
    case CsgOperation::Union:
      return std::any_of(in.begin(), in.end(), [](char c) { return c != 0; });
    case CsgOperation::Intersection:
      return std::all_of(in.begin(), in.end(), [](char c) { return c != 0; });
    case CsgOperation::Difference:
      return in[0] && std::none_of(in.begin() + 1, in.end(), [](char c) { return c != 0; });
  }
  return false;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::vector<BoundaryCrossing> combine_crossings(CsgOperation op,
                                                const std::vector<std::vector<BoundaryCrossing>>& operands) {
  std::vector<BoundaryCrossing> out;
  const size_t n = operands.size();
  std::vector<size_t> next(n, 0), last_at_t(n, 0);
  std::vector<char> in(n, 0);
  bool solid = false;
  for (;;) {
    double t = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n; ++i)
      if (next[i] < operands[i].size()) t = std::min(t, operands[i][next[i]].t);
    if (t == std::numeric_limits<double>::infinity()) break;
    // Every operand's crossings at t, applied together: one that crosses
    // an even number of times there keeps its state.
    const std::vector<char> before = in;
    for (size_t i = 0; i < n; ++i)
      for (; next[i] < operands[i].size() && operands[i][next[i]].t == t; ++next[i]) {
        in[i] = !in[i];
        last_at_t[i] = next[i];
      }
    const bool now = inside(op, in);
    if (now == solid) continue;
    // The surface is that of an operand whose change alone makes the
    // solid's; where only changes together do (two operands of an
    // intersection entering at once), that of the first that changed.
    size_t chosen = n;
    for (size_t i = 0; i < n; ++i) {
      if (in[i] == before[i]) continue;
      if (chosen == n) chosen = i;
      std::vector<char> alone = before;
      alone[i] = in[i];
      if (inside(op, alone) == now) {
        chosen = i;
        break;
      }
    }
    BoundaryCrossing c = operands[chosen][last_at_t[chosen]];
    c.entering = now;
    out.push_back(c);
    solid = now;
  }
  return out;
}

}  // namespace caustica

#pragma once

#include <string>
#include <vector>

#include "core/shapes/boundary_crossing.h"

namespace caustica {

// How a csg solid is made of its operands: the points inside any of them,
// inside all of them, or inside the first and none of the others.
enum class CsgOperation { Union, Intersection, Difference };

// Parses "union", "intersection" or "difference".
bool parse_csg_operation(const std::string& name, CsgOperation& out);

// The boundary of the combined solid along a line, from each operand's
// crossings along the same line: every operand's list ascending in t and
// alternating, from outside at t = -infinity, between entering and leaving
// (its `entering` flags are not read). Crossings at the same t are applied
// together, so operands that touch (one leaving where the other enters)
// make no boundary between them, and a tangent touch (in and out at one t)
// makes none either. Each crossing of the result is the one of the operand
// whose change made the solid's, with `entering` set for the solid.
std::vector<BoundaryCrossing> combine_crossings(CsgOperation op,
                                                const std::vector<std::vector<BoundaryCrossing>>& operands);

}  // namespace caustica

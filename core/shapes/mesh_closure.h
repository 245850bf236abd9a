#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math/vec.h"

namespace caustica {

// Why a triangle mesh bounds no solid, or "" if it does: corners at the
// same position are one vertex, and every edge between two of them must
// belong to exactly two triangles that run along it in opposite
// directions (closed and consistently wound). Triangles with two corners
// at one position are left out.
std::string mesh_closure_problem(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices);

}  // namespace caustica

#include "core/shapes/mesh_closure.h"

#include <map>
#include <tuple>

namespace caustica {

std::string mesh_closure_problem(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices) {
  const auto key = [](Vec3 p) { return std::make_tuple(p.x, p.y, p.z); };
  std::map<std::tuple<float, float, float>, uint32_t> vertex_of;
  std::vector<uint32_t> vertex(positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
    vertex[i] = vertex_of.try_emplace(key(positions[i]), uint32_t(vertex_of.size())).first->second;
  // For each undirected edge (lower vertex first): the triangles along it
  // in that direction and against it.
  std::map<std::pair<uint32_t, uint32_t>, std::pair<int, int>> edges;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t v[3] = {vertex[indices[t]], vertex[indices[t + 1]], vertex[indices[t + 2]]};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = v[e], b = v[(e + 1) % 3];
      auto& [along, against] = edges[{std::min(a, b), std::max(a, b)}];
      ++(a < b ? along : against);
    }
  }
  if (edges.empty()) return "it has no triangles";
  size_t open = 0, crowded = 0, unwound = 0;
  for (const auto& [edge, uses] : edges) {
    const auto [along, against] = uses;
    if (along + against < 2)
      ++open;
    else if (along + against > 2)
      ++crowded;
    else if (along != 1)
      ++unwound;
  }
  if (open) return std::to_string(open) + " of its edges belong to one triangle only (it is not closed)";
  if (crowded) return std::to_string(crowded) + " of its edges belong to more than two triangles";
  if (unwound) return std::to_string(unwound) + " of its edges join triangles wound the same way round";
  return "";
}

}  // namespace caustica

#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "core/shapes/boundary_crossing.h"

namespace caustica {

class TriangleMesh;
struct Ray;

// Every crossing of a line with a closed mesh, through an Embree scene of
// its own that reports each hit to a filter instead of keeping the
// nearest. A ray through an edge or a corner meets each triangle there;
// hits that close together facing the same way are one crossing.
class MeshCrossings {
 public:
  MeshCrossings(RTCDevice device, const TriangleMesh& mesh);
  ~MeshCrossings();
  MeshCrossings(const MeshCrossings&) = delete;
  MeshCrossings& operator=(const MeshCrossings&) = delete;

  // Appends the crossings of the whole line o + t d (behind o too),
  // ascending in t, each on leaf `leaf` with the triangle and barycentrics
  // the mesh's interaction() takes.
  void crossings(const Ray& line, uint32_t leaf, std::vector<BoundaryCrossing>& out) const;

 private:
  RTCScene scene_;
  float extent_;  // the mesh's bounding diagonal, for the same-hit tolerance
};

}  // namespace caustica

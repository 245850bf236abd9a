#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "core/geometry/ray.h"
#include "core/media/volume.h"

namespace caustica {

// Upper bounds of a volume's values over the cells of a coarse grid laid
// over its unit cube, so that tracking through a mostly empty volume takes
// long steps where it is empty and skips cells where it is zero.
class MajorantGrid {
 public:
  // `cells` per axis; every bound is scale x the volume's max_in x factor.
  MajorantGrid(const Volume& volume, std::array<int, 3> cells, float scale, float factor);

  // Calls visit(t_begin, t_end, majorant) for each cell `local_ray` (in the
  // volume's coordinates) crosses between t = 0 and t_max, in order, until
  // visit returns false.
  template <class Visit>
  void traverse(const Ray& local_ray, float t_max, Visit&& visit) const;

  float largest() const { return largest_; }

 private:
  float at(int x, int y, int z) const { return bounds_[(size_t(z) * cells_[1] + y) * cells_[0] + x]; }

  std::array<int, 3> cells_;
  std::vector<float> bounds_;
  float largest_ = 0;
};

template <class Visit>
void MajorantGrid::traverse(const Ray& r, float t_max, Visit&& visit) const {
  // Clip to the unit cube.
  float t0 = 0, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    if (r.d[a] == 0) {
      if (!(r.o[a] >= 0 && r.o[a] <= 1)) return;
      continue;
    }
    float ta = -r.o[a] / r.d[a], tb = (1 - r.o[a]) / r.d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1)) return;
  // Walk the cells in order (Amanatides and Woo's traversal).
  const int* n = cells_.data();
  int cell[3], step[3];
  float t_next[3], t_delta[3];
  const Vec3 entry = r.at(t0);
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(int(entry[a] * n[a]), 0, n[a] - 1);
    if (r.d[a] > 0) {
      step[a] = 1;
      t_next[a] = (float(cell[a] + 1) / n[a] - r.o[a]) / r.d[a];
      t_delta[a] = 1 / (n[a] * r.d[a]);
    } else if (r.d[a] < 0) {
      step[a] = -1;
      t_next[a] = (float(cell[a]) / n[a] - r.o[a]) / r.d[a];
      t_delta[a] = -1 / (n[a] * r.d[a]);
    } else {
      step[a] = 0;
      t_next[a] = kInfinity;
      t_delta[a] = kInfinity;
    }
  }
  float t = t0;
  for (;;) {
    const int a = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    const float t_end = std::min(t_next[a], t1);
    if (t_end > t && !visit(t, t_end, at(cell[0], cell[1], cell[2]))) return;
    if (t_end >= t1) return;
    t = t_end;
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= n[a]) return;
    t_next[a] += t_delta[a];
  }
}

}  // namespace caustica

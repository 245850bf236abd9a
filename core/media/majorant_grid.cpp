#include "core/media/majorant_grid.h"

#include <algorithm>

namespace caustica {

MajorantGrid::MajorantGrid(const Volume& volume, std::array<int, 3> cells, float scale, float factor) : cells_(cells) {
  bounds_.resize(size_t(cells[0]) * cells[1] * cells[2]);
  for (int z = 0; z < cells[2]; ++z)
    for (int y = 0; y < cells[1]; ++y)
      for (int x = 0; x < cells[0]; ++x) {
        Bounds3 cell;
        cell.lo = {float(x) / cells[0], float(y) / cells[1], float(z) / cells[2]};
        cell.hi = {float(x + 1) / cells[0], float(y + 1) / cells[1], float(z + 1) / cells[2]};
        const float bound = scale * volume.max_in(cell) * factor;
        bounds_[(size_t(z) * cells[1] + y) * cells[0] + x] = bound;
        largest_ = std::max(largest_, bound);
      }
}

}  // namespace caustica

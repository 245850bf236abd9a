#pragma once

#include <algorithm>
#include <vector>

#include "core/math/vec.h"

namespace caustica {

inline constexpr int kTileSize = 16;

// A block of pixels [lo, hi), the unit of parallel work.
struct Tile {
  Vec2i lo, hi;
  uint64_t pixels() const { return uint64_t(hi.x - lo.x) * uint64_t(hi.y - lo.y); }
};

// The film's tiles in row-major order.
inline std::vector<Tile> make_tiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({{x, y}, {std::min(x + kTileSize, width), std::min(y + kTileSize, height)}});
  return tiles;
}

}  // namespace caustica

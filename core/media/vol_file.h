#pragma once

#include <filesystem>
#include <vector>

#include "core/geometry/bounds.h"

namespace caustica {

// A grid of values as Mitsuba's .vol files store it: "VOL", version 3, an
// encoding (1: 32-bit float), the resolution along x, y and z, the channels
// per voxel (1 or 3), a bounding box (six floats: min then max), then the
// values, x fastest, channels interleaved, all little-endian.
struct VolGrid {
  int nx = 0, ny = 0, nz = 0, channels = 0;
  Bounds3 bbox;
  std::vector<float> values;

  float at(int x, int y, int z, int c) const { return values[((size_t(z) * ny + y) * nx + x) * channels + c]; }
};

// Reads and checks a .vol file: the header, the size against the file's
// length (before anything is allocated), and every value (finite, at least
// 0). Throws std::runtime_error naming the file and what is wrong.
VolGrid read_vol_file(const std::filesystem::path& file);

}  // namespace caustica

#pragma once

#include <filesystem>
#include <vector>

namespace caustica::test {

// Writes a Mitsuba .vol file (version 3, float32) with `values` x fastest,
// channels interleaved, and the bounding box [0, 1]^3.
void write_vol_file(const std::filesystem::path& file, int nx, int ny, int nz, int channels,
                    const std::vector<float>& values);

}  // namespace caustica::test

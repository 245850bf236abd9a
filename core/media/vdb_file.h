#pragma once

#include <filesystem>
#include <string>

#include "core/media/vol_file.h"

namespace caustica {

// Whether this build reads OpenVDB files (it does where libopenvdb-dev was
// installed when it was configured).
bool reads_vdb_files();

// Reads grid `grid_name` of an OpenVDB file into a dense grid over the box
// of its active voxels: a float grid gives 1 channel, a vec3s grid 3. The
// grid's box is where the file's transform puts those voxels (voxel i's
// centre at index i), so its voxels must be axis-aligned boxes (a linear
// transform without rotation or shear). Values are checked as in .vol
// files: finite, at least 0. Throws std::runtime_error naming the file and
// what is wrong.
VolGrid read_vdb_file(const std::filesystem::path& file, const std::string& grid_name);

}  // namespace caustica

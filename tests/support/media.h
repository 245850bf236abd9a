#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/media/medium.h"
#include "core/media/volume.h"

namespace caustica::test {

// The medium `element` (a <medium> written as in a scene file, without a
// name), made by the scene loader as the interior of a shape.
std::shared_ptr<const Medium> make_medium(const std::string& element);

// The gridvolume of `file`, with filter_type `filter` (and, for a .vdb
// file, its grid `grid`).
std::shared_ptr<const Volume> make_grid_volume(const std::filesystem::path& file,
                                               const std::string& filter = "trilinear",
                                               const std::string& grid = "density");

}  // namespace caustica::test

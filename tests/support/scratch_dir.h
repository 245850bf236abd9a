#pragma once

#include <filesystem>

namespace caustica::test {

// A folder for the files a test executable writes (meshes, images),
// under the system's temporary folder and named for the process; it is
// removed with everything in it when the executable ends, so that runs
// leave nothing behind.
const std::filesystem::path& scratch_dir();

}  // namespace caustica::test

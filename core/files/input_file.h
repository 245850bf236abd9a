#pragma once

#include <filesystem>
#include <string>

namespace caustica {

// Why `file` cannot be read as an input (a mesh, an image, a volume, a
// spectrum), as the end of a sentence naming it: "not found", "is a
// directory", or "is not a regular file" (a device such as /dev/zero or a
// pipe, which a reader would wait on or read without end); empty when it
// can be read.
std::string input_file_problem(const std::filesystem::path& file);

}  // namespace caustica

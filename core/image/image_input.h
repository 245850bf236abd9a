#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "core/image/image_output.h"

namespace caustica {

// Reads every channel of an image file as float, and its string metadata.
// Throws std::runtime_error naming the file.
Image read_image(const std::filesystem::path& path, std::map<std::string, std::string>* metadata = nullptr);

// Throws std::runtime_error naming the file if it is a display image (PNG
// or JPEG: tone-mapped and encoded for a screen), which measuring errors
// against a linear render would mislead.
void require_linear_image(const std::filesystem::path& path);

}  // namespace caustica

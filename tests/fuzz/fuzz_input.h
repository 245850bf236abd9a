#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace caustica::fuzz {

// Writes a fuzzer's input to a file of this process (in /dev/shm where
// there is one) with the extension given, and returns its path: for the
// inputs caustica reads by file name.
std::filesystem::path input_file(const uint8_t* data, size_t size, const std::string& extension);

// A scene file's text around one shape, texture or other element.
std::string scene_with(const std::string& element);

}  // namespace caustica::fuzz

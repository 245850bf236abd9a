#pragma once

#include <filesystem>
#include <functional>

namespace caustica {

// Writes a file through `write`, which receives a temporary path beside the
// destination (same extension, so format detection still works) and must
// create it; then renames it over the destination in one step. A failed or
// interrupted write leaves any previous file untouched.
void write_atomically(const std::filesystem::path& destination,
                      const std::function<void(const std::filesystem::path&)>& write);

}  // namespace caustica

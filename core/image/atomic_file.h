#pragma once

#include <filesystem>
#include <functional>

namespace caustica {

// Writes a file through `write`, which receives a temporary path beside the
// destination (same extension, so format detection still works) and must
// create it; then renames it over the destination in one step. A failed or
// interrupted write leaves any previous file untouched. Temporary files
// that killed processes left in the destination's folder are removed.
void write_atomically(const std::filesystem::path& destination,
                      const std::function<void(const std::filesystem::path&)>& write);

// Removes the temporary file a write_atomically in progress has made, if
// any. Async-signal-safe: for a signal handler that is about to end the
// process while a file is written.
void remove_pending_temporary_file();

}  // namespace caustica

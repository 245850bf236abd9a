#include "core/image/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>

namespace caustica {

namespace {

// The temporary file being written, as a signal handler can read it: the
// path is complete before `pending` is set, and only unlink() reads it.
char pending_path[4096];
std::atomic<bool> pending{false};

}  // namespace

void remove_pending_temporary_file() {
  if (pending.exchange(false)) unlink(pending_path);
}

void write_atomically(const std::filesystem::path& destination,
                      const std::function<void(const std::filesystem::path&)>& write) {
  // Appended piecewise: g++ 12 warns falsely (-Wrestrict) on "literal" + string&&.
  std::string name = ".";
  name += destination.stem().string();
  name += ".tmp";
  name += std::to_string(getpid());
  name += destination.extension().string();
  std::filesystem::path tmp = destination;
  tmp.replace_filename(name);
  const std::string native = tmp.string();
  const bool tracked = native.size() < sizeof(pending_path) && !pending.load();
  if (tracked) {
    std::memcpy(pending_path, native.c_str(), native.size() + 1);
    pending.store(true);
  }
  try {
    write(tmp);
    std::filesystem::rename(tmp, destination);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    if (tracked) pending.store(false);
    throw;
  }
  if (tracked) pending.store(false);
}

}  // namespace caustica

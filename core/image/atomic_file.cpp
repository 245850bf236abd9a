#include "core/image/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// The temporary file being written, as a signal handler can read it: the
// path is complete before `pending` is set, and only unlink() reads it.
char pending_path[4096];
std::atomic<bool> pending{false};

// The process id in a temporary file's name as write_atomically makes it
// (".stem.tmpPID.ext", or ".stem.tmpPID" without an extension), or 0.
pid_t writer_of(const std::string& name) {
  const size_t tmp = name.rfind(".tmp");
  if (name.empty() || name[0] != '.' || tmp == std::string::npos || tmp == 0) return 0;
  size_t end = tmp + 4;
  pid_t pid = 0;
  while (end < name.size() && name[end] >= '0' && name[end] <= '9' && pid < 100000000)
    pid = pid * 10 + (name[end++] - '0');
  if (end == tmp + 4 || (end < name.size() && (name[end] != '.' || name.find('.', end + 1) != std::string::npos)))
    return 0;
  return pid;
}

// A process killed mid-write (SIGKILL, which no handler sees) leaves its
// temporary file behind: those of processes that no longer exist are
// removed from the folder by the next write into it.
void remove_stale_temporaries(const std::filesystem::path& folder) {
  std::error_code error;
  for (const auto& entry :
       std::filesystem::directory_iterator(folder.empty() ? std::filesystem::path(".") : folder, error)) {
    const pid_t pid = writer_of(entry.path().filename().string());
    if (pid > 0 && pid != getpid() && kill(pid, 0) == -1 && errno == ESRCH && entry.is_regular_file(error))
      std::filesystem::remove(entry.path(), error);
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
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
  remove_stale_temporaries(destination.parent_path());
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

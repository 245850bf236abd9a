#include "core/image/atomic_file.h"

#include <unistd.h>

#include <stdexcept>
#include <string>

namespace caustica {

void write_atomically(const std::filesystem::path& destination,
                      const std::function<void(const std::filesystem::path&)>& write) {
  std::filesystem::path tmp = destination;
  tmp.replace_filename("." + destination.stem().string() + ".tmp" + std::to_string(getpid()) +
                       destination.extension().string());
  try {
    write(tmp);
    std::filesystem::rename(tmp, destination);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace caustica

#include "core/image/atomic_file.h"

#include <unistd.h>

#include <stdexcept>
#include <string>

namespace caustica {

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

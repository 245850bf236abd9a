#include "core/install/data_files.h"

#include <dlfcn.h>

#include <optional>
#include <system_error>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// The installed data folder beside the binary that holds this code, if
// there is one.
std::optional<std::filesystem::path> installed_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&installed_folder), &info) == 0 || !info.dli_fname) return std::nullopt;
  std::error_code error;
  const std::filesystem::path binary = std::filesystem::canonical(info.dli_fname, error);
  if (error) return std::nullopt;
  for (const char* up : {"..", "../../.."}) {
    const std::filesystem::path folder = binary.parent_path() / up / "share" / "caustica";
    if (std::filesystem::is_regular_file(folder / "config.ocio", error))
      return std::filesystem::weakly_canonical(folder, error);
  }
  return std::nullopt;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::filesystem::path data_file(const std::string& name, const std::filesystem::path& build_path) {
  static const std::optional<std::filesystem::path> installed = installed_folder();
  return installed ? *installed / name : build_path;
}

}  // namespace caustica

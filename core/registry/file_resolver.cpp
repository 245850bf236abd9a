#include "core/registry/file_resolver.h"

namespace caustica {

namespace fs = std::filesystem;

fs::path FileResolver::resolve(const fs::path& name, const fs::path& naming_file) const {
  if (name.is_absolute()) return name;
  const fs::path beside = (naming_file.parent_path() / name).lexically_normal();
  std::error_code ec;
  if (fs::exists(beside, ec)) return beside;
  for (const fs::path& folder : folders_)
    if (fs::exists(folder / name, ec)) return (folder / name).lexically_normal();
  if (fs::exists(main_ / name, ec)) return (main_ / name).lexically_normal();
  return beside;
}

}  // namespace caustica

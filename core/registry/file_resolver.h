#pragma once

#include <filesystem>
#include <vector>

namespace caustica {

// Where the files a scene names (includes, meshes, textures, spectra) are
// looked for, in order: beside the file that names them, then in each
// <path> folder (the last given first, as Mitsuba prepends them), then
// beside the main scene file (where Mitsuba looks for every file). The
// first that exists wins; if none does, the name beside the naming file is
// returned, for the error to name.
class FileResolver {
 public:
  explicit FileResolver(std::filesystem::path main_scene_folder) : main_(std::move(main_scene_folder)) {}

  void add_folder(std::filesystem::path folder) { folders_.insert(folders_.begin(), std::move(folder)); }
  std::filesystem::path resolve(const std::filesystem::path& name, const std::filesystem::path& naming_file) const;

 private:
  std::filesystem::path main_;
  std::vector<std::filesystem::path> folders_;
};

}  // namespace caustica

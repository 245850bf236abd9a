#include "tests/support/scene_copy.h"

#include <fstream>
#include <sstream>

namespace caustica::test {

namespace fs = std::filesystem;

fs::path edited_cornell_box(const std::string& name, const std::function<std::string(std::string)>& edit,
                            const std::string& scene) {
  const fs::path source = fs::path(CAUSTICA_SOURCE_DIR) / "scenes";
  const fs::path dir = fs::temp_directory_path() / "caustica_scene_copies" / name;
  fs::create_directories(dir / "cornell");
  if (!fs::exists(dir / "meshes")) fs::create_directory_symlink(source / "meshes", dir / "meshes");
  for (const std::string& file : {scene + ".xml", std::string("cornell/room.xml")}) {
    std::ifstream in(source / file);
    std::ostringstream text;
    text << in.rdbuf();
    std::ofstream(dir / file) << edit(text.str());
  }
  return dir / (scene + ".xml");
}

}  // namespace caustica::test

// Scene files from a string: any input loads or throws a SceneError (or
// another std::exception with a message); nothing crashes or hangs.

#include <cstdint>
#include <exception>
#include <string_view>

#include "core/loader/scene_loader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // Relative file names resolve beside it, inside the scene folder, so the
  // project's meshes and textures are reachable.
  static const std::string where = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/fuzz.xml";
  try {
    caustica::load_scene_string(std::string_view(reinterpret_cast<const char*>(data), size), where);
  } catch (const std::exception&) {
  }
  return 0;
}

// OBJ meshes through the obj shape, as a scene loads them.

#include <cstdint>
#include <exception>

#include "core/loader/scene_loader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = caustica::fuzz::input_file(data, size, ".obj");
  try {
    caustica::load_scene_string(
        caustica::fuzz::scene_with("<shape type='obj'><string name='filename' value='" + file.string() + "'/></shape>"),
        "fuzz.xml");
  } catch (const std::exception&) {
  }
  return 0;
}

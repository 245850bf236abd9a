// Textures read through the image path: the first byte picks the file's
// extension (and so the format OpenImageIO tries first), the rest is the file.

#include <array>
#include <cstdint>
#include <exception>

#include "core/loader/scene_loader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const std::array<const char*, 8> extensions = {".png", ".jpg", ".exr", ".hdr", ".tga", ".bmp", ".ppm", ".tif"};
  const auto file = caustica::fuzz::input_file(data + 1, size - 1, extensions[data[0] % extensions.size()]);
  try {
    caustica::load_scene_string(
        caustica::fuzz::scene_with("<bsdf type='diffuse'><texture type='bitmap' name='reflectance'><string "
                                   "name='filename' value='" +
                                   file.string() + "'/></texture></bsdf>"),
        "fuzz.xml");
  } catch (const std::exception&) {
  }
  return 0;
}

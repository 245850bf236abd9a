// PLY meshes from bytes: any input gives a mesh or a PlyError.

#include <cstdint>
#include <string_view>

#include "core/shapes/ply_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    caustica::read_ply(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const caustica::PlyError&) {
  }
  return 0;
}

// Mitsuba serialized meshes from bytes: any input gives a mesh or a
// SerializedError. The first byte picks the mesh asked for, so the table of
// offsets at the file's end is exercised too.

#include <cstdint>
#include <string_view>

#include "core/shapes/serialized_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  try {
    caustica::read_serialized(std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1), data[0] % 4);
  } catch (const caustica::SerializedError&) {
  }
  return 0;
}

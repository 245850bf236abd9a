#include "core/media/vol_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// The most voxels a grid may declare: 2^28, as for images.
constexpr uint64_t kMaxVoxels = uint64_t(1) << 28;
constexpr size_t kHeaderBytes = 4 + 4 + 4 * 3 + 4 + 6 * 4;

int32_t read_int(const char* p) {
  uint32_t v = uint32_t(uint8_t(p[0])) | uint32_t(uint8_t(p[1])) << 8 | uint32_t(uint8_t(p[2])) << 16 |
               uint32_t(uint8_t(p[3])) << 24;
  return int32_t(v);
}

float read_float(const char* p) {
  const uint32_t bits = uint32_t(read_int(p));
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

VolGrid read_vol_file(const std::filesystem::path& file) {
  const auto fail = [&](const std::string& problem) { return std::runtime_error(file.string() + ": " + problem); };
  std::ifstream in(file, std::ios::binary);
  if (!in) throw fail("cannot be opened");
  in.seekg(0, std::ios::end);
  const uint64_t length = uint64_t(in.tellg());
  in.seekg(0);
  char header[kHeaderBytes];
  if (length < kHeaderBytes || !in.read(header, kHeaderBytes))
    throw fail("is too short for a volume header (" + std::to_string(length) + " bytes, the header needs " +
               std::to_string(kHeaderBytes) + ")");
  if (std::memcmp(header, "VOL", 3) != 0) throw fail("is not a Mitsuba volume (it does not start with VOL)");
  if (header[3] != 3) throw fail("has volume format version " + std::to_string(int(header[3])) + "; only 3 is read");
  const int32_t encoding = read_int(header + 4);
  if (encoding != 1)
    throw fail("stores its values with encoding " + std::to_string(encoding) + "; only 1 (32-bit float) is read");
  VolGrid grid;
  grid.nx = read_int(header + 8);
  grid.ny = read_int(header + 12);
  grid.nz = read_int(header + 16);
  grid.channels = read_int(header + 20);
  if (grid.nx <= 0 || grid.ny <= 0 || grid.nz <= 0)
    throw fail("declares a resolution of " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " x " +
               std::to_string(grid.nz) + "; each must be at least 1");
  if (grid.channels != 1 && grid.channels != 3)
    throw fail("declares " + std::to_string(grid.channels) + " channels; 1 or 3 are read");
  const uint64_t voxels = uint64_t(grid.nx) * uint64_t(grid.ny) * uint64_t(grid.nz);
  if (voxels > kMaxVoxels) throw fail("declares " + std::to_string(voxels) + " voxels, more than 2^28");
  const uint64_t data_bytes = voxels * uint64_t(grid.channels) * 4;
  if (length - kHeaderBytes != data_bytes)
    throw fail("declares " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " x " +
               std::to_string(grid.nz) + " x " + std::to_string(grid.channels) + " values (" +
               std::to_string(data_bytes) + " bytes) but holds " + std::to_string(length - kHeaderBytes));
  grid.bbox.lo = {read_float(header + 24), read_float(header + 28), read_float(header + 32)};
  grid.bbox.hi = {read_float(header + 36), read_float(header + 40), read_float(header + 44)};
  std::vector<char> bytes(data_bytes);
  if (!in.read(bytes.data(), std::streamsize(data_bytes))) throw fail("could not be read to its end");
  grid.values.resize(size_t(voxels) * grid.channels);
  for (size_t i = 0; i < grid.values.size(); ++i) {
    const float v = read_float(bytes.data() + 4 * i);
    if (!(v >= 0) || !std::isfinite(v))
      throw fail("holds the value " + std::to_string(v) + " at byte " + std::to_string(kHeaderBytes + 4 * i) +
                 "; values must be finite and at least 0");
    grid.values[i] = v;
  }
  return grid;
}

}  // namespace caustica

#include "tests/support/vol_writer.h"

#include <cstdint>
#include <fstream>

namespace caustica::test {

void write_vol_file(const std::filesystem::path& file, int nx, int ny, int nz, int channels,
                    const std::vector<float>& values) {
  std::ofstream out(file, std::ios::binary);
  out.write("VOL\x03", 4);
  const auto put_int = [&](int32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  const auto put_float = [&](float v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  put_int(1);
  put_int(nx);
  put_int(ny);
  put_int(nz);
  put_int(channels);
  for (float v : {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f}) put_float(v);
  for (float v : values) put_float(v);
}

}  // namespace caustica::test

#include "tests/support/env_map_file.h"

#include <vector>

#include "core/image/image_output.h"

namespace caustica::test {

std::filesystem::path write_env_map(const std::string& name, const std::function<Color(int, int)>& value, int w,
                                    int h) {
  Image image{w, h, {"R", "G", "B"}, std::vector<float>(size_t(w) * h * 3)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Color c = value(x, y);
      float* p = &image.pixels[(size_t(y) * w + x) * 3];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
  write_exr(path, image, {}, false);
  return path;
}

}  // namespace caustica::test

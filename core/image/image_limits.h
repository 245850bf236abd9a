#pragma once

#include <cstdint>
#include <string>

namespace caustica {

// The largest image caustica reads, renders or allocates: at most 65536
// pixels a side and 2^28 pixels (16384 x 16384) in all. A file's declared
// size is checked against it before any pixel is allocated, as a file of a
// few bytes can declare gigapixels.
inline constexpr int64_t kMaxImageSide = 65536;
inline constexpr int64_t kMaxImagePixels = int64_t(1) << 28;

// Empty when width x height is a size caustica accepts, else what is wrong.
inline std::string image_size_problem(int64_t width, int64_t height) {
  if (width <= 0 || height <= 0)
    return "its size " + std::to_string(width) + "x" + std::to_string(height) + " is empty";
  if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
    return "its size " + std::to_string(width) + "x" + std::to_string(height) +
           " exceeds the limit of 65536 pixels a side and 2^28 pixels in all";
  return {};
}

}  // namespace caustica

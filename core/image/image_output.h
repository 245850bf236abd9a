#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace caustica {

// A float image with named channels, pixel-interleaved, top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;
};

// Writes a linear OpenEXR file (float or half) with string metadata; atomic.
void write_exr(const std::filesystem::path& path, const Image& image,
               const std::map<std::string, std::string>& metadata, bool half_float);

// Writes display-referred 8-bit RGB (values in [0, 1] after the display
// transform; clamped here) to a PNG; atomic.
void write_png8(const std::filesystem::path& path, int width, int height, const std::vector<float>& display_rgb);

}  // namespace caustica

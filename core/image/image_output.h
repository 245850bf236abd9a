#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace caustica {

// A float image with named channels, pixel-interleaved, top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;

  // The position of a channel in each pixel, or -1 if the image has none of that name.
  int channel_index(const std::string& name) const {
    for (size_t c = 0; c < channels.size(); ++c)
      if (channels[c] == name) return int(c);
    return -1;
  }
};

// An image made row by row when asked, so that a large one is written
// without being held whole: `fill` writes rows [y_begin, y_end),
// pixel-interleaved, channels.size() values per pixel.
struct ImageRows {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::function<void(int y_begin, int y_end, float* out)> fill;
  // Channels a half-float file still holds in float.
  std::vector<std::string> float_only;
};
ImageRows rows_of(const Image& image);

// Values a file may not hold as they are: those a half-float file would turn
// into infinities (beyond 65504, half's largest, in magnitude), and those at
// float's largest magnitude, where a larger value was clamped.
struct ExtremeValues {
  size_t beyond_half = 0, at_float_limit = 0;
};
ExtremeValues count_extreme_values(const ImageRows& rows);

// Writes a linear OpenEXR file (float or half, rows.float_only in float
// either way) with string metadata, a band of rows at a time; atomic.
void write_exr(const std::filesystem::path& path, const ImageRows& rows,
               const std::map<std::string, std::string>& metadata, bool half_float);
void write_exr(const std::filesystem::path& path, const Image& image,
               const std::map<std::string, std::string>& metadata, bool half_float);

// Writes the named channels of `image` (R, G, B for Radiance RGBE; R, G,
// B or Y for PFM) as a .hdr or .pfm file, as the extension says; atomic.
void write_plain_float(const std::filesystem::path& path, const Image& image, const std::vector<std::string>& channels);

// Quantises display-referred RGB in [0, 1] to `bits` (8 or 16) per channel.
// 8-bit output is dithered with triangular noise of +-1 step (a pure function
// of the pixel, so outputs are reproducible): smooth gradients then show
// noise finer than the eye resolves instead of bands.
// `display_rgb` holds whole rows, the first of them row `first_row`.
std::vector<uint16_t> quantize(std::span<const float> display_rgb, int width, int bits, int first_row = 0);

// Writes display-referred RGB (in [0, 1]) as an 8- or 16-bit PNG; atomic.
void write_png(const std::filesystem::path& path, int width, int height, const std::vector<float>& display_rgb,
               int bits = 8);

}  // namespace caustica

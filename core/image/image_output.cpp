#include "core/image/image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>

#include "core/image/atomic_file.h"
#include "core/sampling/pcg32.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Opens `path` for `spec`, lets `write` write the pixels (whole, or a band
// of rows at a time) and closes it; any failure names the file.
void write_with_oiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec,
                     const std::function<bool(OIIO::ImageOutput&)>& write) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "': " + OIIO::geterror());
  if (!out->open(path.string(), spec) || !write(*out) || !out->close())
    throw std::runtime_error("cannot write '" + path.string() + "': " + out->geterror());
}

// PFM, which OpenImageIO 2.4 reads but cannot write: a text header ("PF"
// for RGB, "Pf" for one channel, the size, and a negative scale for
// little-endian data), then float rows from the bottom up.
void write_pfm(const std::filesystem::path& path, int width, int height, int channels, const float* data) {
  std::ofstream out(path, std::ios::binary);
  out << (channels == 3 ? "PF" : "Pf") << "\n" << width << " " << height << "\n-1.0\n";
  const size_t row = size_t(width) * channels;
  for (int y = height - 1; y >= 0; --y)
    for (size_t i = 0; i < row; ++i) {
      const uint32_t bits = std::bit_cast<uint32_t>(data[size_t(y) * row + i]);
      const char bytes[4] = {char(bits), char(bits >> 8), char(bits >> 16), char(bits >> 24)};
      out.write(bytes, 4);
    }
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

ImageRows rows_of(const Image& image) {
  const size_t row = size_t(image.width) * image.channels.size();
  ImageRows rows{image.width, image.height, image.channels, {}, {}};
  rows.fill = [&image, row](int y_begin, int y_end, float* out) {
    std::copy(image.pixels.begin() + ptrdiff_t(size_t(y_begin) * row),
              image.pixels.begin() + ptrdiff_t(size_t(y_end) * row), out);
  };
  return rows;
}

namespace {
namespace CAUSTICA_UNITY_ID {

// Rows per band: about a million values, at least one row.
int band_rows(const ImageRows& rows) {
  const size_t row = std::max<size_t>(1, size_t(rows.width) * rows.channels.size());
  return int(std::clamp<size_t>((size_t(1) << 20) / row, 1, size_t(std::max(rows.height, 1))));
}

template <class F>
void for_each_band(const ImageRows& rows, F&& f) {
  const int band = band_rows(rows);
  std::vector<float> values(size_t(band) * rows.width * rows.channels.size());
  for (int y = 0; y < rows.height; y += band) {
    const int end = std::min(rows.height, y + band);
    rows.fill(y, end, values.data());
    f(y, end, std::span<const float>(values.data(), size_t(end - y) * rows.width * rows.channels.size()));
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

ExtremeValues count_extreme_values(const ImageRows& rows) {
  ExtremeValues n;
  for_each_band(rows, [&](int, int, std::span<const float> values) {
    for (float v : values) {
      n.beyond_half += std::abs(v) > 65504.0f;
      n.at_float_limit += std::abs(v) >= std::numeric_limits<float>::max();
    }
  });
  return n;
}

void write_exr(const std::filesystem::path& path, const ImageRows& rows,
               const std::map<std::string, std::string>& metadata, bool half_float) {
  OIIO::ImageSpec spec(rows.width, rows.height, int(rows.channels.size()),
                       half_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = rows.channels;
  if (half_float && !rows.float_only.empty())
    for (const std::string& name : rows.channels)
      spec.channelformats.push_back(std::find(rows.float_only.begin(), rows.float_only.end(), name) !=
                                            rows.float_only.end()
                                        ? OIIO::TypeDesc::FLOAT
                                        : OIIO::TypeDesc::HALF);
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    write_with_oiio(tmp, spec, [&](OIIO::ImageOutput& out) {
      bool ok = true;
      for_each_band(rows, [&](int y, int end, std::span<const float> values) {
        ok = ok && out.write_scanlines(y, end, 0, OIIO::TypeDesc::FLOAT, values.data());
      });
      return ok;
    });
  });
}

void write_exr(const std::filesystem::path& path, const Image& image,
               const std::map<std::string, std::string>& metadata, bool half_float) {
  write_exr(path, rows_of(image), metadata, half_float);
}

void write_plain_float(const std::filesystem::path& path, const Image& image,
                       const std::vector<std::string>& channels) {
  const size_t n = channels.size(), stride = image.channels.size(), pixels = size_t(image.width) * image.height;
  std::vector<int> from;
  for (const std::string& name : channels) {
    from.push_back(image.channel_index(name));
    if (from.back() < 0) throw std::logic_error("write_plain_float: the image has no channel " + name);
  }
  std::vector<float> data(pixels * n);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t c = 0; c < n; ++c) data[p * n + c] = image.pixels[p * stride + size_t(from[c])];
  OIIO::ImageSpec spec(image.width, image.height, int(n), OIIO::TypeDesc::FLOAT);
  spec.channelnames = channels;
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    if (path.extension() == ".pfm")
      write_pfm(tmp, image.width, image.height, int(n), data.data());
    else
      write_with_oiio(tmp, spec,
                      [&](OIIO::ImageOutput& out) { return out.write_image(OIIO::TypeDesc::FLOAT, data.data()); });
  });
}

std::vector<uint16_t> quantize(std::span<const float> display_rgb, int width, int bits, int first_row) {
  if (bits != 8 && bits != 16) throw std::invalid_argument("PNG bit depth must be 8 or 16");
  const float levels = bits == 8 ? 255.0f : 65535.0f;
  std::vector<uint16_t> out(display_rgb.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const float v = std::isfinite(display_rgb[i]) ? std::clamp(display_rgb[i], 0.0f, 1.0f) : 0.0f;
    float noise = 0;
    if (bits == 8) {
      const size_t pixel = i / 3;
      const uint64_t h =
          mix_bits((uint64_t(pixel % width) << 32) ^ (pixel / width + size_t(first_row)) ^ (uint64_t(i % 3) << 62));
      // The sum of two uniforms in [0, 1), less 1: triangular on (-1, 1).
      noise = float(h & 0xffffffu) * 0x1p-24f + float((h >> 32) & 0xffffffu) * 0x1p-24f - 1;
    }
    out[i] = uint16_t(std::clamp(std::lround(v * levels + noise), 0L, long(levels)));
  }
  return out;
}

void write_png(const std::filesystem::path& path, int width, int height, const std::vector<float>& display_rgb,
               int bits) {
  const OIIO::TypeDesc type = bits == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16;
  const OIIO::ImageSpec spec(width, height, 3, type);
  // Quantised a band of rows at a time: no second whole image beside the first.
  const int band = std::max(1, (1 << 18) / std::max(1, 3 * width));
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    write_with_oiio(tmp, spec, [&](OIIO::ImageOutput& out) {
      bool ok = true;
      std::vector<uint8_t> bytes;
      for (int y = 0; ok && y < height; y += band) {
        const int end = std::min(height, y + band);
        const std::span<const float> rows(display_rgb.data() + size_t(y) * width * 3, size_t(end - y) * width * 3);
        const std::vector<uint16_t> q = quantize(rows, width, bits, y);
        if (bits == 16) {
          ok = out.write_scanlines(y, end, 0, type, q.data());
        } else {
          bytes.assign(q.begin(), q.end());
          ok = out.write_scanlines(y, end, 0, type, bytes.data());
        }
      }
      return ok;
    });
  });
}

}  // namespace caustica

#include "core/image/image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "core/image/atomic_file.h"
#include "core/sampling/pcg32.h"

namespace caustica {

namespace {

void write_with_oiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc data_type,
                     const void* data) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "': " + OIIO::geterror());
  if (!out->open(path.string(), spec) || !out->write_image(data_type, data) || !out->close())
    throw std::runtime_error("cannot write '" + path.string() + "': " + out->geterror());
}

}  // namespace

size_t values_beyond_half(const Image& image) {
  size_t n = 0;
  for (float v : image.pixels) n += std::abs(v) > 65504.0f;
  return n;
}

size_t values_at_float_limit(const Image& image) {
  size_t n = 0;
  for (float v : image.pixels) n += std::abs(v) >= std::numeric_limits<float>::max();
  return n;
}

void write_exr(const std::filesystem::path& path, const Image& image,
               const std::map<std::string, std::string>& metadata, bool half_float) {
  OIIO::ImageSpec spec(image.width, image.height, int(image.channels.size()),
                       half_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.channels;
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    write_with_oiio(tmp, spec, OIIO::TypeDesc::FLOAT, image.pixels.data());
  });
}

std::vector<uint16_t> quantize(const std::vector<float>& display_rgb, int width, int bits) {
  if (bits != 8 && bits != 16) throw std::invalid_argument("PNG bit depth must be 8 or 16");
  const float levels = bits == 8 ? 255.0f : 65535.0f;
  std::vector<uint16_t> out(display_rgb.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const float v = std::isfinite(display_rgb[i]) ? std::clamp(display_rgb[i], 0.0f, 1.0f) : 0.0f;
    float noise = 0;
    if (bits == 8) {
      const size_t pixel = i / 3;
      const uint64_t h = mix_bits((uint64_t(pixel % width) << 32) ^ (pixel / width) ^ (uint64_t(i % 3) << 62));
      // The sum of two uniforms in [0, 1), less 1: triangular on (-1, 1).
      noise = float(h & 0xffffffu) * 0x1p-24f + float((h >> 32) & 0xffffffu) * 0x1p-24f - 1;
    }
    out[i] = uint16_t(std::clamp(std::lround(v * levels + noise), 0L, long(levels)));
  }
  return out;
}

void write_png(const std::filesystem::path& path, int width, int height, const std::vector<float>& display_rgb,
               int bits) {
  const std::vector<uint16_t> q = quantize(display_rgb, width, bits);
  if (bits == 8) {
    const std::vector<uint8_t> bytes(q.begin(), q.end());
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    write_atomically(path, [&](const std::filesystem::path& tmp) {
      write_with_oiio(tmp, spec, OIIO::TypeDesc::UINT8, bytes.data());
    });
  } else {
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT16);
    write_atomically(
        path, [&](const std::filesystem::path& tmp) { write_with_oiio(tmp, spec, OIIO::TypeDesc::UINT16, q.data()); });
  }
}

}  // namespace caustica

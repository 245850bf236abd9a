#include "core/image/image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "core/image/atomic_file.h"

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

void write_png8(const std::filesystem::path& path, int width, int height, const std::vector<float>& display_rgb) {
  std::vector<uint8_t> bytes(display_rgb.size());
  for (size_t i = 0; i < bytes.size(); ++i) {
    const float v = std::isfinite(display_rgb[i]) ? std::clamp(display_rgb[i], 0.0f, 1.0f) : 0.0f;
    bytes[i] = uint8_t(std::lround(v * 255));
  }
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  write_atomically(
      path, [&](const std::filesystem::path& tmp) { write_with_oiio(tmp, spec, OIIO::TypeDesc::UINT8, bytes.data()); });
}

}  // namespace caustica

#include "core/image/image_input.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/image/image_limits.h"

namespace caustica {

void require_linear_image(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".png" || ext == ".jpg" || ext == ".jpeg")
    throw std::runtime_error("'" + path.string() +
                             "' is a display image (tone-mapped and encoded for a screen); errors are measured on "
                             "linear renders (.exr, .hdr, .pfm): give the EXR written beside it");
}

Image read_image(const std::filesystem::path& path, std::map<std::string, std::string>* metadata) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("cannot read image '" + path.string() + "': " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (const std::string problem = image_size_problem(spec.width, spec.height); !problem.empty())
    throw std::runtime_error("cannot read image '" + path.string() + "': " + problem);
  if (spec.nchannels <= 0 || spec.nchannels > 1024)
    throw std::runtime_error("cannot read image '" + path.string() + "': it has " + std::to_string(spec.nchannels) +
                             " channels");
  Image image{spec.width, spec.height, spec.channelnames, {}};
  image.pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error("cannot read image '" + path.string() + "': " + in->geterror());
  if (metadata)
    for (const OIIO::ParamValue& p : spec.extra_attribs)
      if (p.type() == OIIO::TypeDesc::STRING) (*metadata)[p.name().string()] = p.get_string();
  return image;
}

}  // namespace caustica

#include "core/cli/tonemap_command.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

#include "core/image/image_input.h"
#include "core/job/develop_settings.h"

namespace caustica {

void TonemapCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("tonemap", "develop a rendered EXR into a PNG again");
  command_->add_option("input", input_, "EXR written by caustica render")->required()->check(CLI::ExistingFile);
  command_->add_option("-o,--output", output_, "output PNG")->required();
  develop_.add_to(*command_);
}

int TonemapCommand::run() const {
  std::map<std::string, std::string> metadata;
  const Image image = read_image(input_, &metadata);
  const auto has = [&](const char* name) {
    return std::find(image.channels.begin(), image.channels.end(), name) != image.channels.end();
  };
  if (!has("R") || !has("G") || !has("B")) throw std::invalid_argument("'" + input_ + "' has no R, G, B channels");
  const Developer developer = develop_.make(nullptr, std::nullopt, recorded_degrees_per_pixel(metadata));
  bool glare_spread = false;
  write_png(output_, image.width, image.height, developer.develop(image, &glare_spread), develop_.png_bits());
  std::printf("%s -> %s (%s)%s\n", input_.c_str(), output_.c_str(), developer.describe().c_str(),
              developer.glare().mode == GlareMode::Clipped && !glare_spread
                  ? "; glare skipped, no pixel exceeds the display's range"
                  : "");
  return 0;
}

}  // namespace caustica

#include "core/cli/render_command.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/color/display_transform.h"
#include "core/image/image_output.h"
#include "core/render/renderer.h"
#include "core/scene/scene_loader.h"
#include "core/version.h"

namespace caustica {

std::map<std::string, std::string> parse_defines(const std::vector<std::string>& items) {
  std::map<std::string, std::string> out;
  for (const std::string& item : items) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw std::invalid_argument("-D expects name=value, got '" + item + "'");
    out[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return out;
}

void RenderCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("render", "render a scene to OUT.exr (linear) and OUT.png (display)");
  command_->add_option("scene", scene_, "Mitsuba 3 scene file")->required()->check(CLI::ExistingFile);
  command_->add_option("-o,--output", output_, "output EXR (default: SCENE_NAME.exr); the PNG goes beside it");
  auto* spp = command_->add_option("--spp", spp_, "samples per pixel (default: the scene's sampler)");
  command_->add_option("--time", time_, "render for this many seconds instead")->excludes(spp);
  command_->add_option("--integrator", integrator_, "replace the scene's integrator (default parameters)");
  command_->add_option("-D", defines_, "define a scene parameter: -D name=value")->allow_extra_args(false);
  command_->add_option("--threads", threads_, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  command_->add_option("--seed", seed_, "random seed");
  command_->add_option("--display", display_, "OpenColorIO display for the PNG");
  command_->add_option("--view", view_, "OpenColorIO view for the PNG");
  command_->add_option("--ocio-config", ocio_config_, "OpenColorIO config (default: $OCIO, else caustica's own)");
  command_->add_option("--debug-pixel", debug_pixel_, "replay one sample of pixel X,Y and print it");
  command_->add_option("--debug-sample", debug_sample_, "the sample index --debug-pixel replays");
  command_->add_flag("-q,--quiet", quiet_, "print nothing but errors");
}

namespace {

std::string replay_command(const std::string& scene, SampleId id, uint64_t seed) {
  return "caustica render " + scene + " --seed " + std::to_string(seed) + " --debug-pixel " +
         std::to_string(id.pixel.x) + "," + std::to_string(id.pixel.y) + " --debug-sample " + std::to_string(id.index);
}

}  // namespace

int RenderCommand::run() const {
  auto scene = load_scene(scene_, parse_defines(defines_));
  if (!integrator_.empty()) scene->set_integrator(make_default_integrator(integrator_));
  const Film& film_settings = *scene->sensor().film();

  if (!debug_pixel_.empty()) {
    int x = -1, y = -1;
    char comma = 0;
    std::istringstream in(debug_pixel_);
    if (!(in >> x >> comma >> y) || comma != ',' || x < 0 || y < 0 || x >= film_settings.width() ||
        y >= film_settings.height())
      throw std::invalid_argument("--debug-pixel expects X,Y inside the film, got '" + debug_pixel_ + "'");
    const auto values = replay_sample(*scene, {x, y}, debug_sample_, seed_);
    const auto names = scene->integrator()->channels();
    for (size_t c = 0; c < values.size(); ++c) std::printf("%s = %.9g\n", names[c].c_str(), values[c]);
    return 0;
  }

  std::filesystem::path exr = output_.empty() ? std::filesystem::path(scene_).stem().string() + ".exr" : output_;
  if (exr.extension() != ".exr") throw std::invalid_argument("output must end in .exr: " + exr.string());
  const DisplayTransform display(ocio_config_.empty() ? default_ocio_config() : std::filesystem::path(ocio_config_),
                                 display_, view_);

  RenderOptions options;
  options.spp = spp_;
  options.time_limit = time_;
  options.seed = seed_;
  options.threads = threads_;
  FilmBuffer film(film_settings.width(), film_settings.height(), scene->integrator()->channels());
  const bool tty = isatty(STDERR_FILENO);
  const auto progress = [&](const RenderProgress& p) {
    if (quiet_) return;
    std::string line = p.spp_target ? std::to_string(100 * p.spp_done / p.spp_target) + "% " : "";
    line += std::to_string(p.spp_done) + (p.spp_target ? "/" + std::to_string(p.spp_target) : "") + " spp, " +
            std::to_string(int(p.seconds)) + " s, " + std::to_string(p.seconds > 0 ? p.rays / p.seconds * 1e-6 : 0) +
            " Mrays/s";
    std::fprintf(stderr, tty ? "\r%-60s" : "%s\n", line.c_str());
  };
  const RenderStats stats = render(*scene, options, film, progress);
  if (tty && !quiet_) std::fprintf(stderr, "\n");

  Image image{film.width(), film.height(), film.channels(), film.resolve()};
  const std::map<std::string, std::string> metadata = {{"caustica:scene", scene_},
                                                       {"caustica:integrator", scene->integrator()->describe()},
                                                       {"caustica:spp", std::to_string(stats.spp)},
                                                       {"caustica:seconds", std::to_string(stats.seconds)},
                                                       {"caustica:seed", std::to_string(seed_)},
                                                       {"caustica:version", kVersion}};
  write_exr(exr, image, metadata, film_settings.half_float());

  std::vector<float> rgb(size_t(image.width) * image.height * 3);
  const size_t nc = image.channels.size();
  for (size_t p = 0; p < rgb.size() / 3; ++p)
    for (size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = c < nc ? image.pixels[p * nc + c] : 0.0f;
  display.apply(rgb, image.width, image.height);
  std::filesystem::path png = exr;
  png.replace_extension(".png");
  write_png8(png, image.width, image.height, rgb);

  if (!quiet_) {
    std::printf(
        "%s: %s, %dx%d, %u spp in %.2f s, %.3g M samples/s, %.3g M rays/s, %llu non-finite samples dropped -> %s, %s\n",
        scene_.c_str(), scene->integrator()->describe().c_str(), film.width(), film.height(), stats.spp, stats.seconds,
        stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6,
        static_cast<unsigned long long>(stats.dropped), exr.c_str(), png.c_str());
  }
  if (stats.dropped > 0)
    std::fprintf(stderr, "caustica: warning: %llu non-finite samples were dropped; replay the first with:\n  %s\n",
                 static_cast<unsigned long long>(stats.dropped),
                 replay_command(scene_, stats.first_dropped, seed_).c_str());
  return 0;
}

}  // namespace caustica

#include "core/cli/render_command.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "core/cli/interrupt.h"
#include "core/cli/progress_display.h"
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
  command_->add_option("--integrator", integrator_, "replace the scene's integrator: NAME or NAME:param=value,...");
  command_->add_option("-D", defines_, "define a scene parameter: -D name=value")->allow_extra_args(false);
  command_->add_option("--threads", threads_, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  command_->add_option("--seed", seed_, "random seed");
  command_->add_option("--exr-format", exr_format_, "half or float (default: the film's component_format)")
      ->check(CLI::IsMember({"half", "float"}));
  command_->add_option("--debug-pixel", debug_pixel_, "replay one sample of pixel X,Y and print it");
  command_->add_option("--debug-sample", debug_sample_, "the sample index --debug-pixel replays");
  command_->add_flag("-q,--quiet", quiet_, "print nothing but errors");
  develop_.add_to(*command_);
}

namespace {

std::string replay_command(const std::string& scene, SampleId id, uint64_t seed) {
  return "caustica render " + scene + " --seed " + std::to_string(seed) + " --debug-pixel " +
         std::to_string(id.pixel.x) + "," + std::to_string(id.pixel.y) + " --debug-sample " + std::to_string(id.index);
}

// The EXR's layers: the integrator's channels, then for radiance the
// first-hit AOVs, the per-pixel variance of the estimate and the number of
// samples each pixel received. Splatted light reaches a pixel from other
// pixels' samples, and progressive photon mapping keeps no samples, so their
// variance is unknown and the layer is left out.
Image assemble_layers(const FilmBuffer& film, const FilmBuffer* aovs) {
  Image image{film.width(), film.height(), film.channels(), film.resolve()};
  if (!aovs) return image;
  const size_t pixels = size_t(film.width()) * film.height();
  const std::vector<float> aov = aovs->resolve(), variance = film.variance();
  const size_t na = aovs->channel_count(), nc = film.channel_count();
  std::vector<std::string> names = film.channels();
  for (const auto& c : aovs->channels()) names.push_back(c);
  const bool variance_known = !film.has_splats() && !film.has_image();
  if (variance_known)
    for (const char* c : {"variance.R", "variance.G", "variance.B"}) names.push_back(c);
  names.push_back("samples.Y");
  const size_t total = names.size();
  std::vector<float> pixels_out(pixels * total);
  for (size_t p = 0; p < pixels; ++p) {
    float* out = &pixels_out[p * total];
    std::copy_n(&image.pixels[p * nc], nc, out);
    std::copy_n(&aov[p * na], na, out + nc);
    if (variance_known) std::copy_n(&variance[p * 3], 3, out + nc + na);
    out[total - 1] = float(film.sample_count({int(p % film.width()), int(p / film.width())}));
  }
  return {film.width(), film.height(), names, pixels_out};
}

}  // namespace

int RenderCommand::replay(const Scene& scene) const {
  const Film& film = *scene.sensor().film();
  int x = -1, y = -1;
  char comma = 0;
  std::istringstream in(debug_pixel_);
  if (!(in >> x >> comma >> y) || comma != ',' || x < 0 || y < 0 || x >= film.width() || y >= film.height())
    throw std::invalid_argument("--debug-pixel expects X,Y inside the film, got '" + debug_pixel_ + "'");
  const ReplayedSample sample = replay_sample(scene, {x, y}, debug_sample_, seed_);
  const auto names = scene.integrator()->channels();
  for (size_t c = 0; c < sample.values.size(); ++c) std::printf("%s = %.9g\n", names[c].c_str(), sample.values[c]);
  for (const Splat& s : sample.splats.splats())
    std::printf("splat at (%.3f, %.3f) to %s: %.9g %.9g %.9g\n", s.raster.x, s.raster.y, names[s.channel].c_str(),
                s.value.r, s.value.g, s.value.b);
  if (sample.splats.dropped() > 0)
    std::printf("%llu non-finite splats dropped\n", (unsigned long long)sample.splats.dropped());
  return 0;
}

int RenderCommand::run() const {
  // Installed first, so an interrupt while the scene loads still ends in an
  // image (of the first pass) rather than in nothing.
  install_interrupt_handler();
  auto scene = load_scene(scene_, parse_defines(defines_));
  if (!integrator_.empty()) scene->set_integrator(make_integrator(integrator_));
  if (!debug_pixel_.empty()) return replay(*scene);

  const std::filesystem::path exr = output_.empty() ? std::filesystem::path(scene_).stem().string() + ".exr" : output_;
  if (exr.extension() != ".exr") throw std::invalid_argument("output must end in .exr: " + exr.string());
  std::filesystem::path png = exr;
  png.replace_extension(".png");
  // Everything that can fail on bad options fails before the render.
  const Developer developer = develop_.make(scene->tone_operator());
  const Film& film_settings = *scene->sensor().film();

  RenderOptions options;
  options.spp = spp_;
  options.time_limit = time_;
  options.seed = seed_;
  options.threads = threads_;
  options.stop = &interrupt_requested();
  FilmBuffer film(film_settings.width(), film_settings.height(), scene->integrator()->channels());
  const bool radiance = film.channels() == std::vector<std::string>{"R", "G", "B"};
  std::optional<FilmBuffer> aovs;
  if (radiance) aovs.emplace(film_settings.width(), film_settings.height(), standard_aov_channels());
  const std::string plan = scene->integrator()->plan(*scene);
  if (!quiet_ && !plan.empty()) std::printf("%s\n", plan.c_str());
  RenderProgress progress;
  RenderStats stats;
  {
    std::optional<ProgressDisplay> display;
    if (!quiet_) display.emplace(progress, time_);
    stats = render(*scene, options, film, aovs ? &*aovs : nullptr, &progress);
  }

  const Image image = assemble_layers(film, aovs ? &*aovs : nullptr);
  const std::map<std::string, std::string> metadata = {{"caustica:scene", scene_},
                                                       {"caustica:plan", plan},
                                                       {"caustica:integrator", scene->integrator()->describe()},
                                                       {"caustica:spp", std::to_string(stats.spp)},
                                                       {"caustica:seconds", std::to_string(stats.seconds)},
                                                       {"caustica:samples", std::to_string(stats.samples)},
                                                       {"caustica:rays", std::to_string(stats.rays)},
                                                       {"caustica:seed", std::to_string(seed_)},
                                                       {"caustica:interrupted", stats.interrupted ? "true" : "false"},
                                                       {"caustica:develop", developer.describe()},
                                                       {"caustica:version", kVersion}};
  const bool half = exr_format_.empty() ? film_settings.half_float() : exr_format_ == "half";
  write_exr(exr, image, metadata, half);
  write_png(png, image.width, image.height, developer.develop(image), develop_.png_bits());

  if (!quiet_) {
    std::printf(
        "%s: %s, %dx%d, %u spp in %.2f s, %.3g M samples/s, %.3g M rays/s, %llu non-finite samples dropped%s "
        "-> %s, %s\n",
        scene_.c_str(), scene->integrator()->describe().c_str(), film.width(), film.height(), stats.spp, stats.seconds,
        stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6,
        static_cast<unsigned long long>(stats.dropped), stats.interrupted ? ", interrupted" : "", exr.c_str(),
        png.c_str());
  }
  if (stats.dropped > 0)
    std::fprintf(stderr, "caustica: warning: %llu non-finite samples were dropped; replay the first with:\n  %s\n",
                 static_cast<unsigned long long>(stats.dropped),
                 replay_command(scene_, stats.first_dropped, seed_).c_str());
  return 0;
}

}  // namespace caustica

// The public interface (include/caustica/caustica.h) over the engine: the
// command line's own load, job and layers, as the Python module uses them.

#include "caustica/caustica.h"

#include <stdexcept>

#include "core/image/image_output.h"
#include "core/job/range_merge.h"
#include "core/job/render_job.h"
#include "core/job/render_outputs.h"
#include "core/loader/scene_loader.h"
#include "core/version.h"

namespace caustica::api {

struct Scene::Loaded {
  LoadedScene scene;
  std::string name;
};

const char* version() { return kVersion; }

Scene Scene::load(const std::filesystem::path& path, const std::map<std::string, std::string>& defines) {
  return Scene(std::make_shared<const Loaded>(Loaded{load_scene(path, defines), path.string()}));
}

Scene Scene::parse(const std::string& xml, const std::filesystem::path& name,
                   const std::map<std::string, std::string>& defines) {
  return Scene(std::make_shared<const Loaded>(Loaded{load_scene_string(xml, name, defines), name.string()}));
}

const std::string& Scene::name() const { return loaded_->name; }

Render render(const Scene& scene, const RenderOptions& options) {
  RenderSettings settings;
  settings.integrator = options.integrator;
  settings.spp = options.spp;
  settings.first_sample = options.first_sample;
  settings.time_limit = options.time_limit;
  settings.seed = options.seed;
  settings.threads = options.threads;
  using Spectral = RenderOptions::Spectral;
  settings.transport = options.spectral == Spectral::On    ? RenderSettings::Transport::Spectral
                       : options.spectral == Spectral::Off ? RenderSettings::Transport::Rgb
                                                           : RenderSettings::Transport::AsTheSceneNeeds;
  const RenderJob job(scene.loaded_->scene, settings);
  const RenderResult result = job.run();
  const std::optional<FirstHitLayers> first_hit = job.first_hit_layers(result);
  Image image =
      RenderLayers(result.film, first_hit ? &*first_hit : nullptr, result.stats.variance_known, options.raw_sums)
          .image();
  return {image.width, image.height, std::move(image.channels), std::move(image.pixels),
          render_metadata(job, result, scene.loaded_->name, options.raw_sums)};
}

float Render::value(int x, int y, const std::string& channel) const {
  size_t c = 0;
  while (c < channels.size() && channels[c] != channel) ++c;
  if (c == channels.size()) throw std::out_of_range("the render has no channel '" + channel + "'");
  if (x < 0 || y < 0 || x >= width || y >= height)
    throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                            std::to_string(width) + " x " + std::to_string(height) + " render");
  return pixels[(size_t(y) * size_t(width) + size_t(x)) * channels.size() + c];
}

void Render::write_exr(const std::filesystem::path& path, bool half_float) const {
  const RenderFile render{path.string(), {width, height, channels, pixels}, metadata};
  caustica::write_exr(path, render.image, metadata, half_float && half_float_suits(render));
}

}  // namespace caustica::api

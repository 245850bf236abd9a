#include "core/job/render_job.h"

namespace caustica {

RenderJob::RenderJob(LoadedScene scene, RenderSettings settings)
    : scene_(std::move(scene)),
      settings_(std::move(settings)),
      integrator_(settings_.integrator.empty() ? scene_.integrator
                                               : make_integrator(settings_.integrator, scene_.integrator_values)) {}

RenderResult RenderJob::run(RenderProgress* progress) const {
  const Film& film = *scene_->sensor().film();
  RenderResult result{FilmBuffer(film.width(), film.height(), integrator_->channels()), std::nullopt, {}};
  const bool radiance = result.film.channels() == std::vector<std::string>{"R", "G", "B"};
  if (settings_.aovs && radiance)
    result.aovs.emplace(film.width(), film.height(), standard_aov_channels(film.output().alpha),
                        FilmBuffer::Moments::None);
  RenderOptions options;
  options.spp = settings_.spp;
  options.first_sample = settings_.first_sample;
  options.time_limit = settings_.time_limit;
  options.seed = settings_.seed;
  options.threads = settings_.threads;
  options.stop = settings_.stop;
  result.stats = render(*scene_, *integrator_, options, result.film, result.aovs ? &*result.aovs : nullptr, progress);
  return result;
}

ReplayedSample RenderJob::replay(Vec2i pixel, uint64_t index) const {
  return replay_sample(*scene_, *integrator_, pixel, index, settings_.seed);
}

RenderJob load_render_job(const std::filesystem::path& file, const Defines& defines, RenderSettings settings) {
  return RenderJob(load_scene(file, defines), std::move(settings));
}

}  // namespace caustica

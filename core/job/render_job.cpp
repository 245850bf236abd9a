#include "core/job/render_job.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace caustica {

RenderJob::RenderJob(LoadedScene scene, RenderSettings settings)
    : scene_(std::move(scene)),
      settings_(std::move(settings)),
      integrator_(settings_.integrator.empty() ? scene_.integrator
                                               : make_integrator(settings_.integrator, scene_.integrator_values)) {
  // What the command line's option checks refuse, refused here for every
  // other caller (Python, the library) in the command line's words.
  if (settings_.threads < 0 || settings_.threads > kMaxThreads)
    throw std::invalid_argument("threads: Value " + std::to_string(settings_.threads) + " not in range 0 to " +
                                std::to_string(kMaxThreads));
  if (!(settings_.time_limit >= 0) || !std::isfinite(settings_.time_limit))
    throw std::invalid_argument("time: must be a finite number of seconds, not " +
                                std::to_string(settings_.time_limit));
  if (settings_.first_sample > kMaxFirstSample)
    throw std::invalid_argument("first_sample: '" + std::to_string(settings_.first_sample) +
                                "' is not a whole number from 0 to 2^62");
  if (settings_.transport != RenderSettings::Transport::AsTheSceneNeeds) {
    SceneFeatures f = scene_->features();
    force_spectral(f, settings_.transport == RenderSettings::Transport::Spectral);
    scene_->set_features(std::move(f));
  }
  if (settings_.light_selection != RenderSettings::LightSelection::AsTheSceneNeeds) {
    SceneFeatures f = scene_->features();
    force_light_tree(f, settings_.light_selection == RenderSettings::LightSelection::Tree);
    scene_->set_features(std::move(f));
  }
  integrator_->check_scene(*scene_);
}

std::string RenderJob::plan() const {
  std::string plan = integrator_->plan(*scene_);
  if (transport_worth_telling(scene_->features())) {
    if (!plan.empty()) plan += '\n';
    plan += describe_transport(scene_->features());
  }
  return plan;
}

RenderResult RenderJob::run(RenderProgress* progress) const {
  const Film& film = *scene_->sensor().film();
  RenderResult result{FilmBuffer(film.width(), film.height(), integrator_->channels()), {}};
  RenderOptions options;
  options.spp = settings_.spp;
  options.first_sample = settings_.first_sample;
  options.time_limit = settings_.time_limit;
  options.seed = settings_.seed;
  options.threads = settings_.threads;
  options.stop = settings_.stop;
  result.stats = render(*scene_, *integrator_, options, result.film, progress);
  return result;
}

std::optional<FirstHitLayers> RenderJob::first_hit_layers(const RenderResult& result) const {
  if (!settings_.aovs || result.film.channels() != std::vector<std::string>{"R", "G", "B"}) return std::nullopt;
  return std::optional<FirstHitLayers>(std::in_place, *scene_, settings_.seed, settings_.first_sample, result.film,
                                       settings_.threads);
}

ReplayedSample RenderJob::replay(Vec2i pixel, uint64_t index) const {
  return replay_sample(*scene_, *integrator_, pixel, index, settings_.seed);
}

RenderJob load_render_job(const std::filesystem::path& file, const Defines& defines, RenderSettings settings) {
  return RenderJob(load_scene(file, defines), std::move(settings));
}

}  // namespace caustica

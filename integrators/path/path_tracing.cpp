#include "integrators/path/path_tracing.h"

#include "integrators/path/path_radiance.h"

namespace caustica {

Color trace_path(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings,
                 const CausticEstimator* caustics, Wavelengths* wavelengths) {
  if (scene.features().medium_walk) {
    PathRadiance<true> radiance(scene, sampler, settings, caustics, wavelengths);
    random_walk(scene, ray, Color(1), TransportMode::Radiance, camera_walk_limits(settings), sampler, radiance,
                scene.sensor().medium(), wavelengths);
    return radiance.L;
  }
  PathRadiance<false> radiance(scene, sampler, settings, caustics, wavelengths);
  random_walk(scene, ray, Color(1), TransportMode::Radiance, camera_walk_limits(settings), sampler, radiance, nullptr,
              wavelengths);
  return radiance.L;
}

}  // namespace caustica

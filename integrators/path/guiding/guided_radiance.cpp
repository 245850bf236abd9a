#include "integrators/path/guiding/guided_radiance.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

template <bool kMedia>
GuidedPathSample walk(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings, GuidingTree& tree,
                      const GuidedWalk& walk, Wavelengths* wavelengths, const Medium* medium) {
  GuidedRadiance<kMedia> radiance(scene, sampler, settings, wavelengths, tree, walk);
  random_walk(scene, ray, Color(1), TransportMode::Radiance, camera_walk_limits(settings), sampler, radiance, medium,
              wavelengths);
  radiance.finish();
  return {radiance.L, radiance.seen, radiance.cost};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

GuidedPathSample trace_guided_path(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings,
                                   GuidingTree& tree, const GuidedWalk& guided, Wavelengths* wavelengths) {
  if (scene.features().medium_walk)
    return walk<true>(scene, ray, sampler, settings, tree, guided, wavelengths, scene.sensor().medium());
  return walk<false>(scene, ray, sampler, settings, tree, guided, wavelengths, nullptr);
}

}  // namespace caustica

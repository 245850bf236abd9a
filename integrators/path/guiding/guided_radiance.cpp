#include "integrators/path/guiding/guided_radiance.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

template <bool kMedia>
Color walk(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings, GuidingTree& tree,
           const GuidedWalk& walk, Wavelengths* wavelengths, const Medium* medium, WalkCost& cost) {
  GuidedRadiance<kMedia> radiance(scene, sampler, settings, wavelengths, tree, walk);
  random_walk(scene, ray, Color(1), TransportMode::Radiance, camera_walk_limits(settings), sampler, radiance, medium,
              wavelengths);
  radiance.finish();
  cost = radiance.cost;
  return radiance.L;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Color trace_guided_path(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings, GuidingTree& tree,
                        const GuidedWalk& guided, Wavelengths* wavelengths, WalkCost& cost) {
  if (scene.features().medium_walk)
    return walk<true>(scene, ray, sampler, settings, tree, guided, wavelengths, scene.sensor().medium(), cost);
  return walk<false>(scene, ray, sampler, settings, tree, guided, wavelengths, nullptr, cost);
}

}  // namespace caustica

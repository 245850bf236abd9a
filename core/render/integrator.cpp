#include "core/render/integrator.h"

#include <stdexcept>

#include "core/registry/properties.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

template <class Can>
std::string integrators_that(const Can& can) {
  std::vector<std::string> able;
  for (const std::string& name : Registry::instance().names("integrator"))
    if (can(*Registry::instance().create_default<Integrator>("integrator", name, {"", 0}))) able.push_back(name);
  return join_names(able);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void Integrator::check_scene(const Scene& scene) const {
  const SceneFeatures& f = scene.features();
  if (f.medium_walk && !renders_media())
    throw std::invalid_argument("integrator '" + plugin_name() +
                                "' does not render participating media or null surfaces yet, which " + scene.source() +
                                " has; render it with " +
                                integrators_that([](const Integrator& i) { return i.renders_media(); }));
  if (f.motion && !renders_motion())
    throw std::invalid_argument(
        "integrator '" + plugin_name() + "' does not render moving shapes or cameras yet, which " + scene.source() +
        " has; render it with " + integrators_that([](const Integrator& i) { return i.renders_motion(); }));
  if (f.light_path_only_lights > 0 && !traces_all_light_from_lights())
    throw std::invalid_argument(
        "integrator '" + plugin_name() + "' cannot see the directionalarea light of " + scene.source() +
        " (each of its points emits along its normal only, a direction no path from the camera or a surface "
        "finds); render it with " +
        integrators_that([](const Integrator& i) { return i.traces_all_light_from_lights(); }));
  if (!f.spectral) return;
  const std::string spectral = "spectral transport (" + f.spectral_reason + ")";
  if (!renders_spectral())
    throw std::invalid_argument(
        "integrator '" + plugin_name() + "' does not render with " + spectral + " yet; render " + scene.source() +
        " with " + integrators_that([](const Integrator& i) { return i.renders_spectral(); }) + ", or in RGB");
  if (f.medium_walk)
    throw std::invalid_argument(scene.source() + ": participating media cannot be rendered with " + spectral +
                                " yet; render it in RGB");
  if (!f.rgb_only_materials.empty())
    throw std::invalid_argument(scene.source() + ": its materials " + join_names(f.rgb_only_materials) +
                                " cannot be rendered with " + spectral + " yet; render it in RGB");
}

}  // namespace caustica

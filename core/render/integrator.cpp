#include "core/render/integrator.h"

#include <stdexcept>

#include "core/registry/properties.h"
#include "core/scene/scene.h"

namespace caustica {

void Integrator::check_scene(const Scene& scene) const {
  if (!scene.features().medium_walk || renders_media()) return;
  std::vector<std::string> able;
  for (const std::string& name : Registry::instance().names("integrator"))
    if (Registry::instance().create_default<Integrator>("integrator", name, {"", 0})->renders_media())
      able.push_back(name);
  throw std::invalid_argument("integrator '" + plugin_name() + "' does not render participating media or null " +
                              "surfaces yet, which " + scene.source() + " has; render it with " + join_names(able));
}

}  // namespace caustica

#include "core/cli/develop_options.h"

#include "core/cli/number_checks.h"
#include "core/registry/registry.h"

namespace caustica {

void DevelopOptions::add_to(CLI::App& command) {
  command.add_option("--tonemap", settings_.tonemap,
                     "tone operator: " + join_names(Registry::instance().names("tonemap")));
  command.add_option("--exposure", settings_.exposure, "exposure in stops, before the tone operator")
      ->check(finite_number())
      ->check(CLI::Range(-100.0, 100.0));
  command
      .add_option("--glare", settings_.glare,
                  "the eye's glare: none, whole (every pixel spread) or clipped (what exceeds 1)")
      ->check(CLI::IsMember({"none", "whole", "clipped"}));
  command
      .add_option("--degrees-per-pixel", settings_.degrees_per_pixel,
                  "the view's degrees per pixel for glare (default: the camera's, or the EXR's record)")
      ->check(finite_number())
      ->check(CLI::PositiveNumber);
  command.add_option("--display", settings_.display, "OpenColorIO display (default: the config's)");
  command.add_option("--view", settings_.view, "OpenColorIO view (default: the display's first)");
  command.add_option("--look", settings_.look, "OpenColorIO look to apply");
  command.add_option("--ocio-config", settings_.ocio_config,
                     "OpenColorIO config (default: $OCIO, else caustica's own)");
  command.add_option("--png-bits", png_bits_, "PNG bit depth, 8 (dithered) or 16")->check(CLI::IsMember({8, 16}));
}

Developer DevelopOptions::make(const std::shared_ptr<ToneOperator>& scene_default,
                               const std::optional<LdrDevelopment>& ldr,
                               std::optional<double> degrees_per_pixel) const {
  return make_developer(settings_, scene_default, ldr, degrees_per_pixel);
}

}  // namespace caustica

#include "core/cli/develop_options.h"

#include "core/cli/number_checks.h"
#include "core/registry/properties.h"

namespace caustica {

void DevelopOptions::add_to(CLI::App& command) {
  command.add_option("--tonemap", tonemap_, "tone operator: " + join_names(Registry::instance().names("tonemap")));
  command.add_option("--exposure", exposure_, "exposure in stops, before the tone operator")
      ->check(finite_number())
      ->check(CLI::Range(-100.0, 100.0));
  command
      .add_option("--glare", glare_, "the eye's glare: none, whole (every pixel spread) or clipped (what exceeds 1)")
      ->check(CLI::IsMember({"none", "whole", "clipped"}));
  command
      .add_option("--degrees-per-pixel", degrees_per_pixel_,
                  "the view's degrees per pixel for glare (default: the camera's, or the EXR's record)")
      ->check(finite_number())
      ->check(CLI::PositiveNumber);
  command.add_option("--display", display_, "OpenColorIO display (default: the config's)");
  command.add_option("--view", view_, "OpenColorIO view (default: the display's first)");
  command.add_option("--look", look_, "OpenColorIO look to apply");
  command.add_option("--ocio-config", ocio_config_, "OpenColorIO config (default: $OCIO, else caustica's own)");
  command.add_option("--png-bits", png_bits_, "PNG bit depth, 8 (dithered) or 16")->check(CLI::IsMember({8, 16}));
}

namespace {

// An ldrfilm's tone mapping as one of caustica's operators.
std::shared_ptr<ToneOperator> ldr_tone_operator(const LdrDevelopment& d) {
  const std::string name = d.tonemap == "reinhard" ? "reinhard" : "none";
  const PluginInfo* info = Registry::instance().find("tonemap", name);
  const SourceLocation where{"ldrfilm", 0};
  Properties props(*info, where);
  props.set("exposure", {ValueKind::Float, double(d.exposure), where});
  if (name == "reinhard") {
    props.set("key", {ValueKind::Float, double(d.key), where});
    props.set("burn", {ValueKind::Float, double(d.burn), where});
  }
  return std::dynamic_pointer_cast<ToneOperator>(info->create(props));
}

}  // namespace

Developer DevelopOptions::make(const std::shared_ptr<ToneOperator>& scene_default,
                               const std::optional<LdrDevelopment>& ldr,
                               std::optional<double> degrees_per_pixel) const {
  std::shared_ptr<ToneOperator> op;
  if (!tonemap_.empty()) {
    const PluginInfo* info = Registry::instance().find("tonemap", tonemap_);
    if (!info)
      throw std::invalid_argument("unknown tone operator '" + tonemap_ +
                                  "' (available: " + join_names(Registry::instance().names("tonemap")) + ")");
    op = Registry::instance().create_default<ToneOperator>("tonemap", tonemap_, {"--tonemap", 0});
  } else if (scene_default) {
    op = scene_default;
  } else if (ldr) {
    op = ldr_tone_operator(*ldr);
  } else {
    op = Registry::instance().create_default<ToneOperator>("tonemap", "none", {"--tonemap", 0});
  }
  if (exposure_) op->set_exposure(*exposure_);
  const std::filesystem::path config =
      ocio_config_.empty() ? default_ocio_config() : std::filesystem::path(ocio_config_);
  std::optional<float> gamma;
  if (ldr && ldr->gamma > 0 && display_.empty() && view_.empty()) gamma = ldr->gamma;
  Glare glare;
  glare.mode = glare_ ? parse_glare_mode(*glare_) : scene_default ? scene_default->glare() : GlareMode::None;
  if (glare.mode != GlareMode::None) {
    if (degrees_per_pixel_)
      glare.degrees_per_pixel = *degrees_per_pixel_;
    else if (!degrees_per_pixel)
      throw std::invalid_argument(
          "glare needs the degrees per pixel of the view, which the image does not record: give --degrees-per-pixel");
    else if (!(*degrees_per_pixel > 0))
      throw std::invalid_argument(
          "glare needs a camera with a field of view (this one's rays are parallel): give --degrees-per-pixel");
    else
      glare.degrees_per_pixel = *degrees_per_pixel;
  }
  return Developer(op, DisplayTransform(config, display_, view_, look_), gamma, glare);
}

}  // namespace caustica

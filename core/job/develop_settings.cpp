#include "core/job/develop_settings.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/registry/properties.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

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

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Developer make_developer(const DevelopSettings& settings, const std::shared_ptr<ToneOperator>& scene_default,
                         const std::optional<LdrDevelopment>& ldr, std::optional<double> degrees_per_pixel) {
  std::shared_ptr<ToneOperator> op;
  if (!settings.tonemap.empty()) {
    const PluginInfo* info = Registry::instance().find("tonemap", settings.tonemap);
    if (!info)
      throw std::invalid_argument("unknown tone operator '" + settings.tonemap +
                                  "' (available: " + join_names(Registry::instance().names("tonemap")) + ")");
    op = Registry::instance().create_default<ToneOperator>("tonemap", settings.tonemap, {"--tonemap", 0});
  } else if (scene_default) {
    op = scene_default;
  } else if (ldr) {
    op = ldr_tone_operator(*ldr);
  } else {
    op = Registry::instance().create_default<ToneOperator>("tonemap", "none", {"--tonemap", 0});
  }
  if (settings.exposure) op->set_exposure(*settings.exposure);
  const std::filesystem::path config =
      settings.ocio_config.empty() ? default_ocio_config() : std::filesystem::path(settings.ocio_config);
  std::optional<float> gamma;
  if (ldr && ldr->gamma > 0 && settings.display.empty() && settings.view.empty()) gamma = ldr->gamma;
  Glare glare;
  glare.mode = settings.glare  ? parse_glare_mode(*settings.glare)
               : scene_default ? scene_default->glare()
                               : GlareMode::None;
  if (glare.mode != GlareMode::None) {
    if (settings.degrees_per_pixel)
      glare.degrees_per_pixel = *settings.degrees_per_pixel;
    else if (!degrees_per_pixel)
      throw std::invalid_argument(
          "glare needs the degrees per pixel of the view, which the image does not record: give --degrees-per-pixel");
    else if (!(*degrees_per_pixel > 0))
      throw std::invalid_argument(
          "glare needs a camera with a field of view (this one's rays are parallel): give --degrees-per-pixel");
    else
      glare.degrees_per_pixel = *degrees_per_pixel;
  }
  return Developer(op, DisplayTransform(config, settings.display, settings.view, settings.look), gamma, glare);
}

std::optional<double> recorded_degrees_per_pixel(const std::map<std::string, std::string>& metadata) {
  const auto angle = metadata.find("caustica:degrees_per_pixel");
  if (angle == metadata.end()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(angle->second.c_str(), &end);
  if (end == angle->second.c_str() || *end != '\0' || !(value > 0) || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace caustica

#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/color/developer.h"
#include "core/film/film.h"

namespace caustica {

// What turns a render into a displayed image, as `render` and `tonemap`
// take it on the command line (--tonemap, --exposure, --glare,
// --degrees-per-pixel, --display, --view, --look, --ocio-config) and
// Python's develop() as arguments; empty or unset means the default.
struct DevelopSettings {
  std::string tonemap, display, view, look, ocio_config;
  std::optional<float> exposure;
  std::optional<std::string> glare;
  std::optional<double> degrees_per_pixel;
};

// The settings' tone operator, else `scene_default`, else the ldrfilm's
// development, else `none`; the settings' exposure replaces the operator's
// own, and a display or view an ldrfilm's gamma. Glare is the settings',
// else the scene's (its tonemap's glare parameter), spread at the
// settings' degrees per pixel, else at `degrees_per_pixel` (the camera's,
// or what the EXR records). Throws std::invalid_argument naming what is
// wrong.
Developer make_developer(const DevelopSettings& settings, const std::shared_ptr<ToneOperator>& scene_default,
                         const std::optional<LdrDevelopment>& ldr = std::nullopt,
                         std::optional<double> degrees_per_pixel = std::nullopt);

// The degrees per pixel a render's metadata records
// (caustica:degrees_per_pixel), if it records a positive finite number.
std::optional<double> recorded_degrees_per_pixel(const std::map<std::string, std::string>& metadata);

}  // namespace caustica

#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "core/color/developer.h"
#include "core/film/film.h"

namespace caustica {

// The command-line settings that turn a render into a PNG, shared by
// `render` and `tonemap`: --tonemap, --exposure, --glare,
// --degrees-per-pixel, --display, --view, --look, --ocio-config and
// --png-bits.
class DevelopOptions {
 public:
  void add_to(CLI::App& command);
  // The --tonemap operator, else `scene_default`, else the ldrfilm's
  // development, else `none`; --exposure replaces the operator's own
  // exposure, and --display or --view an ldrfilm's gamma. Glare is
  // --glare's, else the scene's (its tonemap's glare parameter), spread at
  // --degrees-per-pixel, else at `degrees_per_pixel` (the camera's, or
  // what the EXR records).
  Developer make(const std::shared_ptr<ToneOperator>& scene_default,
                 const std::optional<LdrDevelopment>& ldr = std::nullopt,
                 std::optional<double> degrees_per_pixel = std::nullopt) const;
  int png_bits() const { return png_bits_; }

 private:
  std::string tonemap_, display_, view_, look_, ocio_config_;
  std::optional<float> exposure_;
  std::optional<std::string> glare_;
  std::optional<double> degrees_per_pixel_;
  int png_bits_ = 8;
};

}  // namespace caustica

#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "core/job/develop_settings.h"

namespace caustica {

// The command-line settings that turn a render into a PNG, shared by
// `render` and `tonemap`: --tonemap, --exposure, --glare,
// --degrees-per-pixel, --display, --view, --look, --ocio-config and
// --png-bits.
class DevelopOptions {
 public:
  void add_to(CLI::App& command);
  // make_developer() with the options given.
  Developer make(const std::shared_ptr<ToneOperator>& scene_default,
                 const std::optional<LdrDevelopment>& ldr = std::nullopt,
                 std::optional<double> degrees_per_pixel = std::nullopt) const;
  int png_bits() const { return png_bits_; }

 private:
  DevelopSettings settings_;
  int png_bits_ = 8;
};

}  // namespace caustica

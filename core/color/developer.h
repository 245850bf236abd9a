#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/color/display_transform.h"
#include "core/color/glare.h"
#include "core/color/tone_operator.h"
#include "core/image/image_output.h"

namespace caustica {

// Turns a scene-referred render into display-referred pixels:
// exposure (2^EV) -> glare, if asked for -> tone operator -> OpenColorIO
// display/view -> clamp,
// or, given a gamma, a plain power curve v^(1/gamma) in place of the
// display transform (Mitsuba 0.x's ldrfilm). Quantisation (with dithering)
// happens when the PNG is written.
class Developer {
 public:
  Developer(std::shared_ptr<ToneOperator> op, DisplayTransform display, std::optional<float> gamma = std::nullopt,
            Glare glare = {})
      : op_(std::move(op)), display_(std::move(display)), gamma_(gamma), glare_(glare) {}

  // Takes the image's R, G, B channels (else its first three, as for AOV
  // renders) as linear Rec.709; returns display-encoded RGB in [0, 1],
  // pixel-interleaved. An image of R, G, B alone is developed in place.
  // `glare_spread`, if given, says whether glare spread any light (not
  // when clipped glare finds nothing beyond the display's range).
  std::vector<float> develop(Image image, bool* glare_spread = nullptr) const;
  const Glare& glare() const { return glare_; }
  std::string describe() const;

 private:
  std::shared_ptr<ToneOperator> op_;
  DisplayTransform display_;
  std::optional<float> gamma_;
  Glare glare_;
};

// Indices of the channels named R, G and B, else of the first three.
std::array<size_t, 3> beauty_channels(const Image& image);

}  // namespace caustica

#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/render/camera_sample.h"

namespace caustica {

class Scene;

// The first-hit layers written beside the beauty (albedo, shading normal,
// depth, and coverage where the film asks for alpha). They are estimated
// from the first kAovSamples samples of each pixel only: noise-free values
// converge within a few samples, and the extra ray per sample then costs
// nothing at high sample counts.
inline constexpr uint32_t kAovSamples = 16;
std::vector<std::string> standard_aov_channels(bool alpha);

// Adds the layers seen along a camera sample to `aovs` if the sample is
// among the first kAovSamples; `scratch` holds a value per layer. The
// scene's film says whether coverage is among them.
void add_standard_aovs(const Scene& scene, const CameraSample& cs, SampleId id, FilmBuffer& aovs,
                       std::vector<float>& scratch);

}  // namespace caustica

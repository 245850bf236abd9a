#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/render/aov_evaluator.h"

namespace caustica {

class Scene;

// The first-hit layers written beside a radiance render's beauty (albedo,
// shading normal, depth, and coverage where the film asks for alpha). They
// average the camera samples among the first kAovSamples indices that the
// render took: for a pixel with n samples in the beauty, indices [first,
// first + n) below kAovSamples. Noise-free values converge within a few
// samples, and their extra ray per sample then costs nothing at high
// sample counts. They are evaluated when the image is written, a band of
// rows at a time, so no film of them is held while rendering.
inline constexpr uint32_t kAovSamples = 16;

class FirstHitLayers {
 public:
  // `beauty` is the render's film, whose counts say which samples it took.
  FirstHitLayers(const Scene& scene, uint64_t seed, uint64_t first_sample, const FilmBuffer& beauty, int threads);

  std::vector<std::string> channels() const { return evaluator_.channels(); }
  // The layers of rows [y_begin, y_end): a film of width x (y_end - y_begin)
  // pixels without moments, its rows from y_begin on. The rays are counted
  // by Scene::layer_rays_traced.
  FilmBuffer evaluate(int y_begin, int y_end) const;

 private:
  const Scene& scene_;
  uint64_t seed_, first_sample_;
  const FilmBuffer& beauty_;
  int threads_;
  AovEvaluator evaluator_;
};

}  // namespace caustica

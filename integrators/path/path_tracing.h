#pragma once

#include <cstdint>

#include "core/bsdf/surface_bsdf.h"
#include "core/geometry/ray.h"
#include "core/math/color.h"
#include "core/render/path_settings.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Scene;

// Light that reaches a surface point from the emitters through one or more
// delta bounces and nothing else (L S+ x): the caustics a photon map holds.
class CausticEstimator {
 public:
  virtual ~CausticEstimator() = default;
  // Radiance leaving `si` toward wo by way of such paths, for a point
  // reached by `camera_segments` segments from the camera.
  virtual Color estimate(const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                         int64_t camera_segments) const = 0;
};

// Radiance along `ray` by unidirectional path tracing: next-event
// estimation and BSDF sampling at every vertex, combined by multiple
// importance sampling (power heuristic), with Russian roulette and
// max_depth as PathSettings describes.
//
// With `caustics`, every vertex with a non-delta lobe also adds the
// estimator's caustic light, and the walk leaves those paths to it: an
// emitter reached through delta bounces only, after a non-delta bounce, is
// not counted again. Nothing is counted twice and nothing is missed.
//
// With `wavelengths` (spectral mode) the result is the path's radiance at
// them, channel i at wavelength i.
Color trace_path(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings,
                 const CausticEstimator* caustics = nullptr, Wavelengths* wavelengths = nullptr);

}  // namespace caustica

#pragma once

#include <optional>
#include <span>

#include "core/sampling/sampler.h"
#include "integrators/bidirectional/path_vertex.h"

namespace caustica {

class Scene;

// A light subpath vertex joined to the lens (the t = 1 strategy).
struct CameraConnection {
  Vec2 raster;        // where it lands on the film
  Color value;        // the unweighted contribution, to be splatted there
  PathVertex camera;  // the lens point, for weighting against other strategies
};

// Connects light[s-1] to the camera: none when the camera cannot see it or
// it sends nothing toward the camera. Delta-position lights and the
// environment are never seen directly, as with camera rays. The sampler
// gives a lens sample only if the camera has a lens. With `wavelengths`
// (spectral mode) the value is at them.
std::optional<CameraConnection> connect_to_camera(const Scene& scene, std::span<const PathVertex> light, int s,
                                                  Sampler& sampler, const Wavelengths* wavelengths = nullptr);

}  // namespace caustica

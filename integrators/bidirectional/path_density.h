#pragma once

#include "integrators/bidirectional/path_vertex.h"

namespace caustica {

class Scene;

// The densities that multiple importance sampling between bidirectional
// strategies compares. Each returns what the subpath samplers in subpath.h
// actually use, converted to the measure of the sampled vertex.

// Density of sampling `next` from `cur`, where `cur` was reached from
// `prev` (null when `cur` starts its subpath): the camera's directional
// density, an emitter's emission density, the BSDF's, or in a medium the
// phase function's. The media's free-flight densities are left out of
// every density alike: the weights stay a function of the path alone, so
// they still sum to one over the strategies.
float scatter_density(const Scene& scene, const PathVertex* prev, const PathVertex& cur, const PathVertex& next);

// For a scattering vertex `cur` between `prev` and `next`: the density of
// `next` sampled from `cur` reached from `prev`, and that of `prev` sampled
// from `cur` reached from `next`; each what scatter_density gives, the
// directions and the BSDF's frame transforms shared.
struct DensityPair {
  float to_next, to_prev;
};
DensityPair scatter_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next);

// Density of a light subpath starting at the light vertex `v` (or the
// emitting surface vertex, or the environment direction): the light
// selection probability times the emitter's position density (its
// direction density for the environment).
float light_origin_density(const Scene& scene, const PathVertex& v);

// Density of `next` as emitted from the light vertex `light`.
float emission_density(const PathVertex& light, const PathVertex& next);

// A solid-angle density at `from` turned into the area density of `to`.
float solid_angle_to_area(const PathVertex& from, const PathVertex& to, float pdf);

}  // namespace caustica

#pragma once

#include <vector>

#include "integrators/bidirectional/path_vertex.h"

namespace caustica {

class Scene;

// The densities that multiple importance sampling between bidirectional
// strategies compares. Each returns what the subpath samplers in subpath.h
// actually use, converted to the measure of the sampled vertex.
//
// A vertex that starts a specular chain (see specular()) is the exception:
// its density is the solid-angle density it was sampled with times the
// cosine at the chain's far end (chain_cos, the vertex's chain_cos_fwd or
// chain_cos_bwd in the direction of sampling). The chain maps the sampled
// direction onto its far end through a Jacobian whose distance part is the
// same from either end (Veach's generalized geometry term is symmetric; for
// ends in different media it differs by the squared ratio of their indices,
// a constant), so that part cancels in every ratio of strategies and the
// result compares strategies as the true densities would. The area density on the chain's
// first surface would not: it grows with how close that surface happens to
// be, and where a glass sphere touches the floor it gave the camera's
// strategy (s = 0) almost all the weight of the sphere's caustic, which
// light tracing finds far better. Every density stays a function of the
// path alone, so the weights still sum to one.

// Density of sampling `next` from `cur`, where `cur` was reached from
// `prev` (null when `cur` starts its subpath): the camera's directional
// density, an emitter's emission density, the BSDF's, or in a medium the
// phase function's. The media's free-flight densities are left out of
// every density alike: the weights stay a function of the path alone, so
// they still sum to one over the strategies.
float scatter_density(const Scene& scene, const PathVertex* prev, const PathVertex& cur, const PathVertex& next,
                      float chain_cos = -1);

// For a scattering vertex `cur` between `prev` and `next`: the density of
// `next` sampled from `cur` reached from `prev`, and that of `prev` sampled
// from `cur` reached from `next`; each what scatter_density gives, the
// directions and the BSDF's frame transforms shared. The chain cosines are
// next's forward and prev's backward one.
struct DensityPair {
  float to_next, to_prev;
};
DensityPair scatter_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next);
// The same with next's chain cosine given: where `next` ends the other
// subpath, a chain from it runs on toward that subpath's start, its
// backward one.
DensityPair scatter_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next,
                              float next_chain_cos);
// The same from the solid-angle densities at `cur` (scattering_both_ways's).
DensityPair area_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next, float forward,
                           float backward);
DensityPair area_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next, float forward,
                           float backward, float next_chain_cos);

// Density of a light subpath starting at the light vertex `v` (or the
// emitting surface vertex, or the environment direction): the light
// selection probability times the emitter's position density (its
// direction density for the environment).
float light_origin_density(const Scene& scene, const PathVertex& v);

// Density of `next` as emitted from the light vertex `light`.
float emission_density(const PathVertex& light, const PathVertex& next, float chain_cos = -1);

// A solid-angle density at `from` turned into the area density of `to`, or
// for a chain start (chain_cos >= 0) into the chain's measure above.
float solid_angle_to_area(const PathVertex& from, const PathVertex& to, float pdf, float chain_cos = -1);

// The chain cosines of every vertex of a subpath, forward and backward.
void find_chain_ends(std::vector<PathVertex>& path);

}  // namespace caustica

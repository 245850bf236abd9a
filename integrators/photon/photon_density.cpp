#include "integrators/photon/photon_density.h"

namespace caustica {

PhotonGather gather_photons(const PhotonMap& map, float radius, const SurfaceInteraction& si, const SurfaceBsdf& bsdf,
                            Vec3 wo, int64_t camera_segments, int64_t max_depth) {
  PhotonGather g;
  map.for_each_within(si.p, radius, [&](const Photon& ph) {
    if (max_depth >= 0 && int64_t(ph.depth) + camera_segments > max_depth) return;
    // Photons on another surface within reach (a wall meeting the floor)
    // are left out; the bias this avoids vanishes with the radius anyway.
    if (dot(ph.n, si.ng) < 0.5f) return;
    const float cos_g = abs_dot(ph.wi, si.ng);
    if (cos_g == 0) return;
    g.flux += bsdf.eval(wo, ph.wi) * ph.power * (abs_dot(ph.wi, si.shading.n) / cos_g);
    ++g.count;
  });
  return g;
}

}  // namespace caustica

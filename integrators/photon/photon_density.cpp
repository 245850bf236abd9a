#include "integrators/photon/photon_density.h"

namespace caustica {

PhotonGather gather_photons(const PhotonMap& map, float radius, const SurfaceInteraction& si, const SurfaceBsdf& bsdf,
                            Vec3 wo, int64_t camera_segments, int64_t max_depth) {
  PhotonGather g;
  const Wavelengths* w = bsdf.wavelengths();
  const bool camera_hero_only = w && secondaries_terminated(*w);
  map.for_each_within(si.p, radius, [&](const Photon& ph) {
    if (max_depth >= 0 && int64_t(ph.depth) + camera_segments > max_depth) return;
    // Photons on another surface within reach (a wall meeting the floor)
    // are left out; the bias this avoids vanishes with the radius anyway.
    if (dot(ph.n, si.ng) < 0.5f) return;
    const float cos_g = abs_dot(ph.wi, si.ng);
    if (cos_g == 0) return;
    Color flux = bsdf.eval(wo, ph.wi) * ph.power * (abs_dot(ph.wi, si.shading.n) / cos_g);
    // A photon that met dispersion counts at the hero wavelength alone,
    // three times over, unless the camera path's termination weighs it so.
    if (ph.hero_only) flux = hero_only(flux) * (camera_hero_only ? 1.0f : 3.0f);
    g.flux += flux;
    ++g.count;
  });
  return g;
}

}  // namespace caustica

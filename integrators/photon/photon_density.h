#pragma once

#include <cstdint>

#include "core/bsdf/surface_bsdf.h"
#include "integrators/photon/photon_map.h"

namespace caustica {

// What a density estimate gathers at a surface point.
struct PhotonGather {
  Color flux;          // sum over the photons found of f(wo, wi) |cos_shading| / |cos_geometric| times their power
  uint64_t count = 0;  // photons found
};

// The photon density kernel of `photon` and `sppm`: the photons of `map`
// within `radius` of si.p (radius at most the map's) that landed on a
// surface facing the same way, whose paths joined to this point's camera
// path of `camera_segments` segments stay within max_depth (-1: no limit).
// Divided by pi radius^2 and the photons emitted, the flux is the radiance
// leaving toward wo by the photons' paths (a uniform disc kernel). Photon
// density is per unit of geometric area, so each photon is divided by its
// geometric cosine; shading uses the shading normal. In spectral mode the
// photons and the BSDF are at the same wavelengths (the round's), and the
// flux is at the BSDF's.
PhotonGather gather_photons(const PhotonMap& map, float radius, const SurfaceInteraction& si, const SurfaceBsdf& bsdf,
                            Vec3 wo, int64_t camera_segments, int64_t max_depth);

}  // namespace caustica

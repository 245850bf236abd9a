#pragma once

#include <cstdint>

namespace caustica {

class Properties;
class Scene;

// The parameters photon and sppm share, read and checked in one place.
struct PhotonSettings {
  int64_t photons = 100000;  // traced per round (iteration)
  float radius = 0;          // initial gather radius; 0 derives it from the scene
  float alpha = 0.7f;        // fraction of new photons kept per round, in (0, 1)
};

PhotonSettings read_photon_settings(const Properties& props);
// Only the radius schedule (radius and alpha), for an integrator whose
// photons are not counted by a parameter (vcm: one light path per pixel).
PhotonSettings read_radius_schedule(const Properties& props);

// The first round's radius: the one given, else 1/200 of the scene's
// bounding-box diagonal.
float initial_radius(const Scene& scene, const PhotonSettings& settings);

// The gather radius of round i (from 0), shrinking so that the rounds'
// average converges (Knaus and Zwicker 2011, eq. 20):
//   r_i^2 = r_0^2 prod_{k=1}^{i} (k + alpha) / (k + 1).
float round_radius(const PhotonSettings& settings, float initial_radius, uint32_t round);

}  // namespace caustica

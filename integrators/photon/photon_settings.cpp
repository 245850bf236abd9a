#include "integrators/photon/photon_settings.h"

#include <algorithm>
#include <cmath>

#include "core/registry/properties.h"
#include "core/scene/scene.h"

namespace caustica {

PhotonSettings read_radius_schedule(const Properties& props) {
  PhotonSettings s;
  s.radius = props.get_float("radius");
  s.alpha = props.get_float("alpha");
  if (!(s.radius >= 0)) throw props.error("radius", "must not be negative");
  if (!(s.alpha > 0 && s.alpha < 1)) throw props.error("alpha", "must be in (0, 1)");
  return s;
}

PhotonSettings read_photon_settings(const Properties& props) {
  PhotonSettings s = read_radius_schedule(props);
  s.photons = props.get_int("photons");
  if (s.photons < 1) throw props.error("photons", "must be at least 1");
  return s;
}

float initial_radius(const Scene& scene, const PhotonSettings& settings) {
  const Vec3 diagonal = scene.bounds().hi - scene.bounds().lo;
  return settings.radius > 0 ? settings.radius : std::max(length(diagonal) / 200, 1e-6f);
}

float round_radius(const PhotonSettings& settings, float initial_radius, uint32_t round) {
  double r2 = double(initial_radius) * initial_radius;
  for (uint32_t k = 1; k <= round; ++k) r2 *= (k + settings.alpha) / (k + 1.0);
  return float(std::sqrt(r2));
}

}  // namespace caustica

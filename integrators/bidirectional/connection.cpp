#include "integrators/bidirectional/connection.h"

#include <cmath>

#include "core/lights/spectral_emission.h"
#include "core/scene/scene.h"
#include "core/transport/emission.h"
#include "core/transport/shadow_transmittance.h"
#include "integrators/bidirectional/path_density.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Strategy (0, t): the camera subpath's last vertex is on an emitter.
// Each environment emitter is a light of its own, weighed on its own.
Color emitted(const Scene& scene, std::vector<PathVertex>& camera, int t, const Wavelengths* wavelengths,
              MisHeuristic heuristic, const Merging& merging) {
  PathVertex& cv = camera[t - 1];
  const std::span<const PathVertex> camera_part = std::span(camera).first(t);
  // The strategy weight takes the place of the MIS weight against next-event estimation.
  const Arrival unweighted;
  Color sum;
  const auto add = [&](const Emitter& emitter, Color Le, float) {
    cv.emitter = &emitter;
    sum +=
        cv.beta * emission_for(emitter, Le, wavelengths) *
        strategy_weight({}, camera_part, 0, t, heuristic, connection_densities(scene, {}, camera_part, 0, t), merging);
  };
  if (cv.environment)
    emission_from_environment(scene, cv.w_env, cv.si.time, unweighted, {}, add);
  else if (cv.emitter)
    emission_at_surface(scene, cv.si, direction_to(cv, camera[t - 2]), unweighted, {}, add);
  return sum;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Color connect(const Scene& scene, std::span<const PathVertex> light, int s, std::vector<PathVertex>& camera, int t,
              Sampler& sampler, const Wavelengths* wavelengths, MisHeuristic heuristic, const Merging& merging) {
  PathVertex& cv = camera[t - 1];
  const std::span<const PathVertex> camera_part = std::span(camera).first(t);
  if (s == 0) return emitted(scene, camera, t, wavelengths, heuristic, merging);
  if (cv.environment || !joinable(cv)) return {};
  const Vec3 wo = direction_to(cv, camera[t - 2]);
  if (s == 1) {
    float u_select = sampler.next_1d();
    const Vec2 u = sampler.next_2d();
    const auto choice = scene.light_selection().sample(u_select);
    if (!choice) return {};
    const auto ls = choice->emitter->sample_Li({cv.p(), cv.si.p_error, cv.si.ng, cv.si.time}, u);
    if (!ls || !(ls->pdf > 0) || ls->Li.is_black()) return {};
    // The value and both densities at the camera end from one frame
    // transform (ls->wi is direction_to(cv, the light point) bit for bit).
    const ScatteringBothWays at_camera = scattering_both_ways(cv, wo, ls->wi);
    Color f = at_camera.f;
    if (f.is_black()) return {};
    f *= shadow_visibility(scene, shadow_ray(cv.si, *ls), medium_toward(cv, ls->wi), sampler);
    if (f.is_black()) return {};
    PathVertex lv;
    lv.kind = PathVertex::Kind::Light;
    lv.emitter = choice->emitter;
    lv.environment = ls->is_infinite;
    lv.w_env = ls->wi;
    lv.si.p = ls->p;
    lv.si.p_error = ls->p_error;
    lv.si.ng = ls->n;
    lv.si.time = cv.si.time;
    lv.delta_light = ls->is_delta;
    lv.pdf_fwd = light_origin_density(scene, lv);
    const float w = strategy_weight({&lv, 1}, camera_part, 1, t, heuristic,
                                    light_sample_densities(scene, camera[t - 2], cv, at_camera, lv), merging);
    return cv.beta * f * emission_for(*choice->emitter, ls->Li, wavelengths) * (w / (choice->pmf * ls->pdf));
  }
  const PathVertex& lv = light[s - 1];
  if (!joinable(lv)) return {};
  const Vec3 d = lv.p() - cv.p();
  const float dist2 = squared_length(d);
  if (dist2 == 0) return {};
  const Vec3 wi = d / std::sqrt(dist2);
  // The BSDF values and the densities the weight needs, from one frame
  // transform at each end (its directions are those the weight would take).
  const ScatteringBothWays at_camera = scattering_both_ways(cv, wo, wi);
  const ScatteringBothWays at_light = scattering_both_ways(lv, direction_to(lv, light[s - 2]), -wi);
  Color f = at_camera.f * at_light.f * (1 / dist2);
  if (f.is_black()) return {};
  f *= shadow_visibility(scene, cv.si.spawn_to(lv.p(), lv.si.p_error, lv.si.ng), medium_toward(cv, wi), sampler);
  if (f.is_black()) return {};
  const ConnectionDensities densities = joined_densities(camera[t - 2], cv, at_camera, light[s - 2], lv, at_light);
  return cv.beta * f * lv.beta * strategy_weight(light.first(s), camera_part, s, t, heuristic, densities, merging);
}

}  // namespace caustica

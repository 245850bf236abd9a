#include "integrators/bidirectional/camera_connection.h"

#include "core/lights/spectral_emission.h"
#include "core/scene/scene.h"
#include "core/transport/shadow_transmittance.h"

namespace caustica {

std::optional<CameraConnection> connect_to_camera(const Scene& scene, std::span<const PathVertex> light, int s,
                                                  Sampler& sampler, const Wavelengths* wavelengths) {
  const PathVertex& v = light[s - 1];
  const Vec2 u_lens = scene.sensor().has_lens() ? sampler.next_2d() : Vec2(0.5f, 0.5f);
  if (v.environment || v.delta_light) return std::nullopt;
  const auto ws = scene.sensor().sample_Wi({v.p(), v.si.p_error, v.si.ng, v.si.time}, u_lens);
  if (!ws || !(ws->pdf > 0)) return std::nullopt;
  Color f;
  if (v.kind == PathVertex::Kind::Light) {
    f = emission_for(*v.emitter, v.emitter->L(v.si, ws->wi), wavelengths) * abs_dot(v.si.ng, ws->wi);
  } else {
    if (!joinable(v)) return std::nullopt;
    f = scattering(v, direction_to(v, light[s - 2]), ws->wi);
  }
  if (f.is_black()) return std::nullopt;
  // A surface hands the ray to the medium on the camera's side of it.
  f *= shadow_visibility(scene, v.si.spawn_to(ws->p_lens, {}, {}), medium_toward(v, ws->wi), sampler);
  if (f.is_black()) return std::nullopt;
  CameraConnection c{ws->raster, v.beta * f * ws->We / ws->pdf, {}};
  c.camera.kind = PathVertex::Kind::Camera;
  c.camera.si.p = ws->p_lens;
  c.camera.si.time = v.si.time;
  return c;
}

}  // namespace caustica

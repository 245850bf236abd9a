#include "bench/batched_path_walk.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "core/lights/spectral_emission.h"
#include "core/render/camera_sample.h"
#include "core/render/direct_light.h"
#include "core/transport/emission.h"
#include "core/transport/random_walk.h"
#include "core/transport/walk_limits.h"
#include "integrators/path/path_tracing.h"

namespace caustica {
namespace {

// One path of a batch: what walk_segments keeps in its locals and
// PathRadiance in its members, between waves.
struct PathSlot {
  Ray ray;
  Color beta{1}, throughput{1}, L;
  float eta_scale = 1;
  Arrival arrival;
  int64_t segments = 1;
  bool alive = true;
  std::optional<SurfaceInteraction> si;
  // Next-event estimation waiting for its shadow ray, and the path's
  // weight at the vertex that took it.
  std::optional<UntestedLightSample> light;
  Color light_beta;
  Ray shadow;
};

constexpr int kPacket = 16;

// Closest hits of the slots `which`, `packet` rays at a time.
void intersect_wave(const Scene& scene, std::vector<PathSlot>& slots, const std::vector<uint32_t>& which, int packet) {
  const EmbreeScene& accel = scene.accel();
  if (packet == 1) {
    for (const uint32_t i : which) slots[i].si = accel.intersect(slots[i].ray);
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (size_t first = 0; first < which.size(); first += kPacket) {
    const size_t n = std::min<size_t>(kPacket, which.size() - first);
    alignas(64) int valid[kPacket];
    alignas(64) RTCRayHit16 rays;
    for (size_t k = 0; k < kPacket; ++k) {
      valid[k] = k < n ? -1 : 0;
      const RTCRay r = to_rtc(slots[which[first + std::min(k, n - 1)]].ray);
      rays.ray.org_x[k] = r.org_x, rays.ray.org_y[k] = r.org_y, rays.ray.org_z[k] = r.org_z;
      rays.ray.dir_x[k] = r.dir_x, rays.ray.dir_y[k] = r.dir_y, rays.ray.dir_z[k] = r.dir_z;
      rays.ray.tnear[k] = r.tnear, rays.ray.tfar[k] = r.tfar, rays.ray.time[k] = r.time;
      rays.ray.mask[k] = r.mask, rays.ray.id[k] = r.id, rays.ray.flags[k] = r.flags;
      rays.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      rays.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, accel.rtc_scene(), &context, &rays);
    for (size_t k = 0; k < n; ++k) {
      PathSlot& s = slots[which[first + k]];
      RTCRayHit hit{};
      hit.ray = to_rtc(s.ray);
      hit.ray.tfar = rays.ray.tfar[k];
      hit.hit = {rays.hit.Ng_x[k], rays.hit.Ng_y[k],   rays.hit.Ng_z[k],   rays.hit.u[k],
                 rays.hit.v[k],    rays.hit.primID[k], rays.hit.geomID[k], {rays.hit.instID[0][k]}};
      s.si = accel.interaction_of(s.ray, hit);
    }
  }
}

// Whether each slot of `which`'s shadow ray is blocked, `packet` at a time.
void occluded_wave(const Scene& scene, const std::vector<PathSlot>& slots, const std::vector<uint32_t>& which,
                   int packet, std::vector<char>& blocked) {
  const EmbreeScene& accel = scene.accel();
  blocked.assign(which.size(), 0);
  if (packet == 1) {
    for (size_t j = 0; j < which.size(); ++j) blocked[j] = accel.occluded(slots[which[j]].shadow);
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (size_t first = 0; first < which.size(); first += kPacket) {
    const size_t n = std::min<size_t>(kPacket, which.size() - first);
    alignas(64) int valid[kPacket];
    alignas(64) RTCRay16 rays;
    for (size_t k = 0; k < kPacket; ++k) {
      valid[k] = k < n ? -1 : 0;
      const RTCRay r = to_rtc(slots[which[first + std::min(k, n - 1)]].shadow);
      rays.org_x[k] = r.org_x, rays.org_y[k] = r.org_y, rays.org_z[k] = r.org_z;
      rays.dir_x[k] = r.dir_x, rays.dir_y[k] = r.dir_y, rays.dir_z[k] = r.dir_z;
      rays.tnear[k] = r.tnear, rays.tfar[k] = r.tfar, rays.time[k] = r.time;
      rays.mask[k] = r.mask, rays.id[k] = r.id, rays.flags[k] = r.flags;
    }
    rtcOccluded16(valid, accel.rtc_scene(), &context, &rays);
    for (size_t k = 0; k < n; ++k) blocked[first + k] = rays.tfar[k] < 0;
  }
}

// walk_segments' body for one path at the vertex it has just hit, with
// PathRadiance's at_vertex, its shadow ray left for the wave to trace.
void shade(const Scene& scene, const PathSettings& settings, const WalkLimits& limits, Sampler& sampler, PathSlot& p) {
  const bool last = limits.max_segments >= 0 && p.segments >= limits.max_segments;
  const bool shows_emission = p.segments > 1 || !settings.hide_emitters;
  if (!p.si) {
    if (shows_emission)
      emission_from_environment(scene, p.ray.d, p.ray.time, p.arrival, {}, [&](const Emitter& e, Color Le, float w) {
        p.L += p.beta * emission_for(e, Le, nullptr) * w;
      });
    p.alive = false;
    return;
  }
  const SurfaceInteraction& si = *p.si;
  const SurfaceBsdf bsdf(*si.shape->bsdf(), si, TransportMode::Radiance, nullptr);
  const Vec3 wo = -p.ray.d;
  if (shows_emission)
    emission_at_surface(scene, si, wo, p.arrival, {},
                        [&](const Emitter& e, Color Le, float w) { p.L += p.beta * emission_for(e, Le, nullptr) * w; });
  if (last) {
    p.alive = false;
    return;
  }
  const float u_select = sampler.next_1d();
  const Vec2 u_light = sampler.next_2d();
  if (bsdf.lobes() & ~kDelta) {
    p.light = untested_light_sample(scene, si, bsdf, wo, u_select, u_light);
    if (p.light) {
      p.light_beta = p.beta;
      p.shadow = shadow_ray(si, p.light->light.ls);
    }
  }
  const float u_lobe = sampler.next_1d();
  const Vec2 u = sampler.next_2d();
  const auto bs = bsdf.sample(wo, u_lobe, u);
  if (!bs) {
    p.alive = false;
    return;
  }
  const Color weight = bs->f * (abs_dot(bs->wi, si.shading.n) / bs->pdf);
  p.beta *= weight;
  p.throughput *= weight;
  if (bs->is_transmission()) p.eta_scale *= bs->eta * bs->eta;
  p.arrival = arrival_from(si, *bs);
  p.ray = si.spawn(bs->wi);
  float q = 1;
  if (!limits.roulette.survives(p.segments, p.throughput, p.eta_scale, sampler, &q)) {
    p.alive = false;
    return;
  }
  p.beta *= 1 / q;
  p.throughput *= 1 / q;
  ++p.segments;
}

}  // namespace

void trace_scalar(const Scene& scene, const PathSettings& settings, uint64_t seed,
                  std::span<const CameraSampleKey> samples, std::span<Color> out) {
  const auto sampler = scene.sensor().sampler()->clone();
  for (size_t i = 0; i < samples.size(); ++i) {
    const CameraSample cs = sample_camera_ray(scene, *sampler, samples[i].pixel, samples[i].index, seed, std::nullopt);
    out[i] = trace_path(scene, cs.ray, *sampler, settings);
  }
}

void trace_batched(const Scene& scene, const PathSettings& settings, uint64_t seed,
                   std::span<const CameraSampleKey> samples, size_t batch, int packet, std::span<Color> out) {
  const WalkLimits limits = camera_walk_limits(settings);
  std::vector<std::unique_ptr<Sampler>> samplers(batch);
  for (auto& s : samplers) s = scene.sensor().sampler()->clone();
  std::vector<PathSlot> slots(batch);
  std::vector<uint32_t> alive, lit;
  std::vector<char> blocked;
  for (size_t first = 0; first < samples.size(); first += batch) {
    const size_t n = std::min(batch, samples.size() - first);
    alive.clear();
    for (size_t j = 0; j < n; ++j) {
      const CameraSampleKey& key = samples[first + j];
      slots[j] = PathSlot{};
      slots[j].ray = sample_camera_ray(scene, *samplers[j], key.pixel, key.index, seed, std::nullopt).ray;
      alive.push_back(uint32_t(j));
    }
    while (!alive.empty()) {
      intersect_wave(scene, slots, alive, packet);
      lit.clear();
      for (const uint32_t j : alive) {
        shade(scene, settings, limits, *samplers[j], slots[j]);
        if (slots[j].light) lit.push_back(j);
      }
      occluded_wave(scene, slots, lit, packet, blocked);
      for (size_t k = 0; k < lit.size(); ++k) {
        PathSlot& p = slots[lit[k]];
        if (!blocked[k]) p.L += p.light_beta * unoccluded_contribution(*p.light);
        p.light.reset();
      }
      std::erase_if(alive, [&](uint32_t j) { return !slots[j].alive; });
    }
    for (size_t j = 0; j < n; ++j) out[first + j] = slots[j].L;
  }
}

}  // namespace caustica

#include "integrators/photon/photon_tracing.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "core/bsdf/surface_bsdf.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {

constexpr uint64_t kBlock = 1024;

void trace_photon(const Scene& scene, PhotonPaths kind, Sampler& sampler, const PathSettings& settings,
                  std::vector<Photon>& out) {
  float u_select = sampler.next_1d();
  const Vec2 u_pos = sampler.next_2d(), u_dir = sampler.next_2d();
  const auto choice = scene.light_selection().sample(u_select);
  if (!choice) return;
  const auto le = choice->emitter->sample_Le(u_pos, u_dir);
  if (!le || !(le->pdf_pos > 0) || !(le->pdf_dir > 0) || le->Le.is_black()) return;
  const float cos = le->n == Vec3() ? 1 : abs_dot(le->n, le->ray.d);
  Color beta = le->Le * (cos / (choice->pmf * le->pdf_pos * le->pdf_dir));
  Color throughput(1);
  Ray ray = le->ray;
  for (uint32_t depth = 1;; ++depth) {
    const auto si = scene.intersect(ray);
    if (!si) return;
    const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, TransportMode::Importance);
    // A photon needs at least one more segment, to the camera.
    const bool within_depth = settings.max_depth < 0 || int64_t(depth) + 1 <= settings.max_depth;
    if (depth >= 2 && within_depth && (bsdf.lobes() & ~kDelta)) out.push_back({si->p, -ray.d, si->ng, beta, depth});
    if (!within_depth) return;
    const float u_lobe = sampler.next_1d();
    const auto bs = bsdf.sample(-ray.d, u_lobe, sampler.next_2d());
    if (!bs) return;
    if (kind == PhotonPaths::Caustic && !bs->is_delta()) return;  // past a non-delta bounce, no caustic
    const Color weight = bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
    beta *= weight;
    throughput *= weight;
    ray = si->spawn(bs->wi);
    if (int64_t(depth) >= settings.rr_depth) {
      const float q = std::min(throughput.max_component(), settings.rr_max_survival);
      if (!(sampler.next_1d() < q)) return;
      beta *= 1 / q;
      throughput *= 1 / q;
    }
  }
}

}  // namespace

std::vector<Photon> trace_photons(const Scene& scene, PhotonPaths kind, uint64_t count, uint32_t round, uint64_t seed,
                                  const PathSettings& settings) {
  const size_t blocks = size_t((count + kBlock - 1) / kBlock);
  std::vector<std::vector<Photon>> found(blocks);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    auto sampler = scene.sensor().sampler()->clone();
    for (uint64_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
      // Keyed apart from every pixel's camera samples.
      sampler->start_sample({-1, int(round)}, i, seed);
      trace_photon(scene, kind, *sampler, settings, found[b]);
    }
  });
  std::vector<Photon> photons;
  for (const auto& f : found) photons.insert(photons.end(), f.begin(), f.end());
  return photons;
}

}  // namespace caustica

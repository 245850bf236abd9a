// Rays per second: caustica's path tracer against Embree alone on the same
// rays. One render of each scene is recorded ray by ray (camera, bounce and
// shadow rays, exactly as the path tracer asked for them) and then replayed,
// all on one thread, three ways:
//   Embree       rtcIntersect1 / rtcOccluded1 on the recorded rays: the limit;
//   SceneQueries caustica's scene queries on the same rays (Embree plus the
//                hit point's interaction: position, normals, uv, error bounds);
//   PathTracer   the whole render (sampling, BSDFs, lights, film) over as many rays.
// The gaps between the three are what caustica spends beside ray queries.

#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "core/job/render_job.h"
#include "core/loader/scene_loader.h"

namespace caustica {
namespace {

constexpr int kRes = 64;
constexpr uint32_t kSpp = 4;

struct Recording {
  LoadedScene scene;
  std::vector<RayLog::Entry> rays;
};

RenderStats render_once(const LoadedScene& scene, uint32_t spp, uint64_t seed) {
  RenderSettings settings;
  settings.spp = spp;
  settings.seed = seed;
  settings.threads = 1;
  settings.aovs = false;
  return RenderJob(scene, settings).run().stats;
}

// Benchmarks run one after another on the main thread, so a plain cache will do.
const Recording& recording(const std::string& name) {
  static std::map<std::string, Recording> cache;
  auto [it, fresh] = cache.try_emplace(name);
  if (fresh) {
    it->second.scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml",
                                  {{"res", std::to_string(kRes)}, {"integrator", "path"}});
    RayLog log;
    it->second.scene->set_ray_log(&log);
    render_once(it->second.scene, kSpp, 0);
    it->second.scene->set_ray_log(nullptr);
    it->second.rays = log.entries();
  }
  return it->second;
}

void BM_Embree(benchmark::State& state, const std::string& name) {
  const Recording& rec = recording(name);
  const RTCScene scene = rec.scene->accel().rtc_scene();
  for (auto _ : state) {
    for (const RayLog::Entry& e : rec.rays) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      if (e.shadow) {
        RTCRay r = to_rtc(e.ray);
        rtcOccluded1(scene, &context, &r);
        benchmark::DoNotOptimize(r.tfar);
      } else {
        RTCRayHit hit{};
        hit.ray = to_rtc(e.ray);
        hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &hit);
        benchmark::DoNotOptimize(hit.hit.geomID);
      }
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations() * rec.rays.size()));
}

void BM_SceneQueries(benchmark::State& state, const std::string& name) {
  const Recording& rec = recording(name);
  const EmbreeScene& accel = rec.scene->accel();
  for (auto _ : state)
    for (const RayLog::Entry& e : rec.rays) {
      if (e.shadow)
        benchmark::DoNotOptimize(accel.occluded(e.ray));
      else
        benchmark::DoNotOptimize(accel.intersect(e.ray));
    }
  state.SetItemsProcessed(int64_t(state.iterations() * rec.rays.size()));
}

void BM_PathTracer(benchmark::State& state, const std::string& name) {
  const Recording& rec = recording(name);
  uint64_t rays = 0, seed = 1;
  for (auto _ : state) rays += render_once(rec.scene, kSpp, seed++).rays;
  state.SetItemsProcessed(int64_t(rays));
}

BENCHMARK_CAPTURE(BM_Embree, cornell_box, std::string("cornell-box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SceneQueries, cornell_box, std::string("cornell-box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathTracer, cornell_box, std::string("cornell-box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Embree, cornell_box_glass, std::string("cornell-box-glass"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SceneQueries, cornell_box_glass, std::string("cornell-box-glass"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathTracer, cornell_box_glass, std::string("cornell-box-glass"))->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace caustica

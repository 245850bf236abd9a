// Rays per second: caustica's path tracer against Embree alone on the same
// rays. One render of each scene is recorded ray by ray (camera, bounce and
// shadow rays, exactly as the path tracer asked for them) and then replayed,
// all on one thread, three ways:
//   Embree       rtcIntersect1 / rtcOccluded1 on the recorded rays: the limit;
//   SceneQueries caustica's scene queries on the same rays (Embree plus the
//                hit point's interaction: position, normals, uv, error bounds);
//   PathTracer   the whole render (sampling, BSDFs, lights, film) over as many rays.
// The gaps between the three are what caustica spends beside ray queries.
// EmbreeBatched/B/N replays the same rays as a walk over batches of B
// paths would ask for them, in packets of N (1, 8 or 16): what tracing in
// packets, the traversal half of a batched walk, could gain.
// Beside the Cornell boxes, a generated scene holds a million-triangle mesh
// (a bumpy sphere in the Cornell room), where traversal dominates.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <vector>

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

// A sphere of rings x segments quads, two triangles each, its radius rippled
// so that neighbouring triangles are not coplanar, as binary PLY.
void write_bumpy_sphere(const std::filesystem::path& path, int rings, int segments) {
  std::vector<float> vertices;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments;
      const double r = 1 + 0.04 * std::sin(23 * theta) * std::sin(17 * phi);
      vertices.insert(vertices.end(), {float(r * std::sin(theta) * std::cos(phi)), float(r * std::cos(theta)),
                                       float(r * std::sin(theta) * std::sin(phi))});
    }
  std::ofstream out(path, std::ios::binary);
  const size_t faces = size_t(2) * rings * segments;
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << vertices.size() / 3
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  out.write(reinterpret_cast<const char*>(vertices.data()), std::streamsize(vertices.size() * sizeof(float)));
  const auto face = [&](int a, int b, int c) {
    const unsigned char n = 3;
    const int32_t v[3] = {a, b, c};
    out.write(reinterpret_cast<const char*>(&n), 1);
    out.write(reinterpret_cast<const char*>(v), sizeof v);
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      face(a, a + segments, b);
      face(b, a + segments, b + segments);
    }
}

// The generated scene's file: the Cornell room and floor around a bumpy
// sphere of 1.2 million triangles, written once into a temporary folder.
std::string generated_scene() {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "caustica-ray-throughput";
  std::filesystem::create_directories(dir);
  write_bumpy_sphere(dir / "bumpy-sphere.ply", 700, 860);
  const std::string scenes = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/";
  std::ofstream(dir / "million-triangles.xml")
      << "<scene version='3.0.0'><include filename='" << scenes << "cornell/room.xml'/>"
      << "<shape type='obj'><string name='filename' value='" << scenes << "meshes/cornell/floor.obj'/>"
      << "<transform name='to_world'><scale value='0.001'/></transform><ref id='white'/></shape>"
      << "<shape type='ply'><string name='filename' value='bumpy-sphere.ply'/>"
      << "<transform name='to_world'><scale value='0.16'/><translate x='0.278' y='0.2' z='0.28'/></transform>"
      << "<ref id='white'/></shape></scene>";
  return (dir / "million-triangles.xml").string();
}

std::string scene_file(const std::string& name) {
  return name == "million-triangles" ? generated_scene()
                                     : std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml";
}

// Benchmarks run one after another on the main thread, so a plain cache will do.
const Recording& recording(const std::string& name) {
  static std::map<std::string, Recording> cache;
  auto [it, fresh] = cache.try_emplace(name);
  if (fresh) {
    // The independent sampler, as the figures in docs/performance.md were measured with
    // it (the scenes' own ldsampler costs about 8 % more a sample).
    it->second.scene = load_scene(scene_file(name),
                                  {{"res", std::to_string(kRes)}, {"integrator", "path"}, {"sampler", "independent"}});
    RayLog log;
    it->second.scene->set_ray_log(&log);
    render_once(it->second.scene, kSpp, 0);
    it->second.scene->set_ray_log(nullptr);
    it->second.rays = log.entries();
  }
  return it->second;
}

// Up to N rays in one of Embree's packets of N (8 or 16), or one by one (N = 1).
template <int N>
void trace(RTCScene scene, bool shadow, std::span<const RTCRay> part) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if constexpr (N == 1) {
    if (shadow) {
      RTCRay r = part[0];
      rtcOccluded1(scene, &context, &r);
      benchmark::DoNotOptimize(r.tfar);
    } else {
      RTCRayHit hit{};
      hit.ray = part[0];
      hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &hit);
      benchmark::DoNotOptimize(hit.hit.geomID);
    }
  } else {
    alignas(64) int valid[N];
    alignas(64) RTCRayHitNt<N> rays;
    for (int i = 0; i < N; ++i) {
      valid[i] = size_t(i) < part.size() ? -1 : 0;
      const RTCRay& r = part[std::min(size_t(i), part.size() - 1)];
      rays.ray.org_x[i] = r.org_x, rays.ray.org_y[i] = r.org_y, rays.ray.org_z[i] = r.org_z;
      rays.ray.dir_x[i] = r.dir_x, rays.ray.dir_y[i] = r.dir_y, rays.ray.dir_z[i] = r.dir_z;
      rays.ray.tnear[i] = r.tnear, rays.ray.tfar[i] = r.tfar, rays.ray.time[i] = r.time;
      rays.ray.mask[i] = r.mask, rays.ray.id[i] = r.id, rays.ray.flags[i] = r.flags;
      rays.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    if constexpr (N == 16) {
      if (shadow)
        rtcOccluded16(valid, scene, &context, reinterpret_cast<RTCRay16*>(&rays.ray));
      else
        rtcIntersect16(valid, scene, &context, reinterpret_cast<RTCRayHit16*>(&rays));
    } else {
      static_assert(N == 8);
      if (shadow)
        rtcOccluded8(valid, scene, &context, reinterpret_cast<RTCRay8*>(&rays.ray));
      else
        rtcIntersect8(valid, scene, &context, reinterpret_cast<RTCRayHit8*>(&rays));
    }
    benchmark::DoNotOptimize(rays.ray.tfar[0]);
    benchmark::DoNotOptimize(rays.hit.geomID[0]);
  }
}

// Traces the recorded rays through Embree alone.
void replay_with_embree(const Recording& rec) {
  const RTCScene scene = rec.scene->accel().rtc_scene();
  for (const RayLog::Entry& e : rec.rays) {
    const RTCRay r = to_rtc(e.ray);
    trace<1>(scene, e.shadow, {&r, 1});
  }
}

void BM_Embree(benchmark::State& state, const std::string& name) {
  const Recording& rec = recording(name);
  for (auto _ : state) replay_with_embree(rec);
  state.SetItemsProcessed(int64_t(state.iterations() * rec.rays.size()));
}

// The recorded rays regrouped as a walk over batches of `batch` paths
// would ask for them, a wave at a time: the batch's camera rays, then its
// first shadow rays, its first bounce rays, its second shadow rays, and so
// on. A path starts at its camera ray, which (the scenes' pinhole's) leaves
// from the camera's position, as no other closest-hit ray does.
struct Wave {
  bool shadow = false;
  std::vector<RTCRay> rays;
};

std::vector<Wave> batched_waves(const Recording& rec, size_t batch) {
  const Vec3 eye = rec.rays.front().ray.o;
  std::vector<std::array<std::vector<RTCRay>, 2>> paths;  // per path: its closest-hit rays, its shadow rays
  for (const RayLog::Entry& e : rec.rays) {
    if (!e.shadow && e.ray.o == eye) paths.emplace_back();
    paths.back()[e.shadow].push_back(to_rtc(e.ray));
  }
  std::vector<Wave> waves;
  for (size_t first = 0; first < paths.size(); first += batch) {
    const size_t end = std::min(paths.size(), first + batch);
    for (size_t k = 0, left = 1; left > 0; ++k) {
      left = 0;
      for (const bool shadow : {false, true}) {
        Wave wave{shadow, {}};
        for (size_t i = first; i < end; ++i)
          if (k < paths[i][shadow].size()) wave.rays.push_back(paths[i][shadow][k]);
        left += wave.rays.size();
        if (!wave.rays.empty()) waves.push_back(std::move(wave));
      }
    }
  }
  return waves;
}

// Batches of range(0) paths, their waves traced in packets of range(1)
// rays (1: one query a ray, in the batched order).
void BM_EmbreeBatched(benchmark::State& state, const std::string& name) {
  const Recording& rec = recording(name);
  const RTCScene scene = rec.scene->accel().rtc_scene();
  const std::vector<Wave> waves = batched_waves(rec, size_t(state.range(0)));
  const size_t width = size_t(state.range(1));
  size_t packets = 0;
  for (const Wave& wave : waves) packets += (wave.rays.size() + width - 1) / width;
  for (auto _ : state)
    for (const Wave& wave : waves)
      for (size_t first = 0; first < wave.rays.size(); first += width) {
        const std::span<const RTCRay> part =
            std::span(wave.rays).subspan(first, std::min(width, wave.rays.size() - first));
        if (width == 16)
          trace<16>(scene, wave.shadow, part);
        else if (width == 8)
          trace<8>(scene, wave.shadow, part);
        else
          trace<1>(scene, wave.shadow, part);
      }
  state.SetItemsProcessed(int64_t(state.iterations() * rec.rays.size()));
  state.counters["rays_per_packet"] = double(rec.rays.size()) / double(packets);
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

// Besides its own rate, the path tracer's share of Embree's: each iteration
// also replays the recorded rays through Embree alone (outside the timed
// part), so the two rates are measured turn about and a machine whose speed
// drifts slows both alike. of_embree is path's rays per second over Embree's.
void BM_PathTracer(benchmark::State& state, const std::string& name) {
  const Recording& rec = recording(name);
  using Clock = std::chrono::steady_clock;
  uint64_t rays = 0, seed = 1;
  double path_seconds = 0, embree_seconds = 0;
  for (auto _ : state) {
    const auto start = Clock::now();
    rays += render_once(rec.scene, kSpp, seed++).rays;
    path_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    state.PauseTiming();
    const auto replay = Clock::now();
    replay_with_embree(rec);
    embree_seconds += std::chrono::duration<double>(Clock::now() - replay).count();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(int64_t(rays));
  const double embree_rays = double(state.iterations()) * double(rec.rays.size());
  state.counters["of_embree"] = (double(rays) / path_seconds) / (embree_rays / embree_seconds);
}

BENCHMARK_CAPTURE(BM_Embree, cornell_box, std::string("cornell-box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SceneQueries, cornell_box, std::string("cornell-box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathTracer, cornell_box, std::string("cornell-box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EmbreeBatched, cornell_box, std::string("cornell-box"))
    ->ArgsProduct({{16, 256}, {1, 8, 16}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Embree, cornell_box_glass, std::string("cornell-box-glass"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SceneQueries, cornell_box_glass, std::string("cornell-box-glass"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathTracer, cornell_box_glass, std::string("cornell-box-glass"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Embree, million_triangles, std::string("million-triangles"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EmbreeBatched, million_triangles, std::string("million-triangles"))
    ->ArgsProduct({{16, 256}, {1, 8, 16}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SceneQueries, million_triangles, std::string("million-triangles"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathTracer, million_triangles, std::string("million-triangles"))->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace caustica

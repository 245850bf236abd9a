// Multiple importance sampling between bidirectional strategies is unbiased
// only if, for every path, the weights of the strategies that could have
// sampled it sum to one. Here paths are made by joining sampled camera and
// light subpaths as bdpt does; each path is then cut at every other vertex,
// each part's densities recomputed from scratch as its own subpath sampler
// would see them, and the weights of all possible strategies summed. The
// weight bdpt computes for the strategy that made the path (with the
// densities the connection overrides) must also equal the recomputed one,
// and for s, t >= 2 be the same bit for bit when those densities come from
// the ends' joint evaluation of value and densities, as bdpt takes them.
// Both are checked to single-precision accuracy; the scenes cover area,
// point, directional and environment lights and diffuse, glossy and delta
// surfaces, and smooth plastic, whose vertices may leave through their delta
// coat yet join connections through the diffuse base. Which strategies are possible is decided from the emitter
// itself, never from the vertex's own flags.

#include "integrators/bidirectional/strategy_weight.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/loader/scene_loader.h"
#include "core/registry/properties.h"
#include "integrators/bidirectional/path_density.h"
#include "integrators/bidirectional/subpath.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const char* const kMixedScene =
    "<scene version='3.0.0'><sensor type='perspective'><float name='fov' value='60'/>"
    "<transform name='to_world'><lookat origin='0, -3, 2' target='0, 0, 0.3' up='0, 0, 1'/></transform>"
    "<film type='hdrfilm'><integer name='width' value='32'/><integer name='height' value='32'/></film></sensor>"
    "<shape type='rectangle'><transform name='to_world'><scale value='4'/></transform>"
    "<bsdf type='diffuse'/></shape>"
    "<shape type='sphere'><point name='center' x='-0.6' y='0' z='0.5'/><float name='radius' value='0.5'/>"
    "<bsdf type='conductor'/></shape>"
    "<shape type='sphere'><point name='center' x='0.6' y='0' z='0.5'/><float name='radius' value='0.5'/>"
    "<bsdf type='roughconductor'><float name='alpha' value='0.2'/></bsdf></shape>"
    "<shape type='sphere'><point name='center' x='0' y='0.8' z='0.3'/><float name='radius' value='0.3'/>"
    "<bsdf type='dielectric'/></shape>"
    "<shape type='sphere'><point name='center' x='-0.2' y='-0.9' z='0.25'/><float name='radius' value='0.25'/>"
    "<bsdf type='plastic'/></shape>"
    "<shape type='sphere'><point name='center' x='0.5' y='-0.5' z='2'/><float name='radius' value='0.2'/>"
    "<emitter type='area'><rgb name='radiance' value='10'/></emitter></shape>"
    "<emitter type='point'><point name='position' x='-1' y='-1' z='2'/><rgb name='intensity' value='5'/></emitter>"
    "<emitter type='constant'><rgb name='radiance' value='0.2'/></emitter></scene>";

std::unique_ptr<Sampler> make_sampler() {
  const PluginInfo* info = Registry::instance().find("sampler", "independent");
  return std::dynamic_pointer_cast<Sampler>(info->create(Properties(*info, {"test", 1})))->clone();
}

// The vertices x_0 (light) .. x_k (camera) of the path strategy (s, t) makes.
std::vector<PathVertex> join(const std::vector<PathVertex>& light, const std::vector<PathVertex>& camera, int s,
                             int t) {
  std::vector<PathVertex> path(light.begin(), light.begin() + s);
  for (int j = t - 1; j >= 0; --j) path.push_back(camera[j]);
  // The connection's endpoints scatter through the connection.
  if (s >= 1) path[s - 1].delta = false;
  path[s].delta = false;
  return path;
}

// Whether the path has a nonzero contribution: each connection or emission
// it relies on sends light. Only such paths need weights that sum to one.
bool carries_light(const Scene& scene, const std::vector<PathVertex>& x, int s) {
  const int k = int(x.size()) - 1;
  if (s == 0) {
    if (x[0].environment) return true;
    return x[0].emitter && !x[0].emitter->L(x[0].si, direction_to(x[0], x[1])).is_black();
  }
  if (x[s].kind == PathVertex::Kind::Camera) {
    Vec2 raster;
    if (scene.sensor().We({x[k].p(), direction_to(x[k], x[s - 1]), kInfinity}, &raster).is_black()) return false;
  } else if (x[s].environment ||
             x[s].bsdf->eval(direction_to(x[s], x[s + 1]), direction_to(x[s], x[s - 1])).is_black()) {
    return false;
  }
  if (s == 1) {
    if (x[0].environment || x[0].delta_light) return true;
    return !x[0].emitter->L(x[0].si, direction_to(x[0], x[1])).is_black();
  }
  if (x[s - 1].bsdf->eval(direction_to(x[s - 1], x[s - 2]), direction_to(x[s - 1], x[s])).is_black()) return false;
  return !scene.occluded(x[s - 1].si.spawn_to(x[s].p(), x[s].si.p_error, x[s].si.ng));
}

// Strategy s' as its own samplers would have made the path: the light
// subpath x_0 .. x_{s'-1} and the camera subpath x_k .. x_{s'}, with their
// densities computed afresh.
float recomputed_weight(const Scene& scene, const std::vector<PathVertex>& x, int sp, MisHeuristic h,
                        const Merging& merging = {}) {
  const int k = int(x.size()) - 1;
  std::vector<PathVertex> light(x.begin(), x.begin() + sp), camera(x.rbegin(), x.rend() - sp);
  if (sp >= 1) light[0].kind = PathVertex::Kind::Light;
  if (sp == 0 && !x[0].environment) camera.back().kind = PathVertex::Kind::Surface;
  compute_densities(scene, light, h, merging);
  compute_densities(scene, camera, h, merging);
  return strategy_weight(light, camera, sp, k + 1 - sp, h, connection_densities(scene, light, camera, sp, k + 1 - sp),
                         merging);
}

// Merging at x_i (0 < i < k) as vcm would have made the path: the light
// subpath x_0 .. x_i merged with the camera subpath x_k .. x_{i+1} that
// went on to x_i itself (so that a specular chain before it ends there).
// The weight from the camera vertex's densities (merge_densities, as vcm
// takes them) must equal the one from the connection's, since the two
// vertices coincide.
float recomputed_merge_weight(const Scene& scene, const std::vector<PathVertex>& x, int i, MisHeuristic h,
                              const Merging& merging) {
  const int k = int(x.size()) - 1;
  std::vector<PathVertex> light(x.begin(), x.begin() + i + 1), camera(x.rbegin(), x.rend() - i);
  light[0].kind = PathVertex::Kind::Light;
  compute_densities(scene, light, h, merging);
  compute_densities(scene, camera, h, merging);
  const std::span<const PathVertex> camera_part = std::span(camera).first(size_t(k - i));
  // Where x_{i+1} scatters through a delta lobe the merge passes the path
  // on through it: the densities it decides there are the delta's, stored
  // as 0, not the connection's evaluation of the BSDF's other lobes.
  ConnectionDensities joined = connection_densities(scene, light, camera_part, i + 1, k - i);
  if (x[size_t(i + 1)].delta) joined.light_end = joined.camera_before_end = 0;
  const float w = merge_weight(light, camera_part, i + 1, k - i, h, joined, merging);
  // vcm's own route: the densities from the camera subpath's vertex at x_i.
  const PathVertex& at = camera[size_t(k - i)];
  const ScatteringBothWays at_merge =
      scattering_both_ways(at, direction_to(at, camera[size_t(k - i - 1)]), direction_to(at, light[size_t(i - 1)]));
  const float own = merge_weight(
      light, camera_part, i + 1, k - i, h,
      merge_densities(light, i + 1, camera[size_t(k - i - 1)], merge_camera_densities(scene, camera, k - i), at_merge),
      merging);
  EXPECT_NEAR(own, w, 1e-4f * std::max(w, 1e-3f)) << "merge at x_" << i << " of a path of " << k << " segments";
  return w;
}

// The light subpath's own density of x_i, sampled from x_{i-1}: the
// subpath x_0 .. x_i's last forward density, computed afresh.
float light_density(const Scene& scene, const std::vector<PathVertex>& x, int i) {
  std::vector<PathVertex> light(x.begin(), x.begin() + i + 1);
  light[0].kind = PathVertex::Kind::Light;
  compute_densities(scene, light, MisHeuristic::Power);
  return light.back().pdf_fwd;
}

// The camera subpath's own density of x_i, sampled from x_{i+1}: the
// subpath x_k .. x_i's last forward density, computed afresh.
float camera_density(const Scene& scene, const std::vector<PathVertex>& x, int i) {
  std::vector<PathVertex> camera(x.rbegin(), x.rend() - i);
  compute_densities(scene, camera, MisHeuristic::Power);
  return camera.back().pdf_fwd;
}

// The same scene lit by the sun: a directional light instead of the sky.
std::string sun_scene() {
  std::string xml = kMixedScene;
  const std::string sky = "<emitter type='constant'><rgb name='radiance' value='0.2'/></emitter>";
  return xml.replace(xml.find(sky), sky.size(),
                     "<emitter type='directional'><vector name='direction' x='0.3' y='0.4' z='-1'/>"
                     "<rgb name='irradiance' value='2'/></emitter>");
}

// Whether no ray can reach the path's first vertex (a point, spot or directional light).
bool delta_light(const PathVertex& origin) { return origin.emitter && origin.emitter->is_delta(); }

bool possible(const std::vector<PathVertex>& x, int sp) {
  const int k = int(x.size()) - 1;
  if (sp == 0) return !delta_light(x[0]);
  if (sp == k && k == 1) return !x[0].environment && !delta_light(x[0]);
  return (sp == 1 || !x[sp - 1].delta) && (sp == k || !x[sp].delta);
}

// How many paths of each kind were checked.
struct Tally {
  int paths = 0, environment = 0, point_light = 0, directional = 0, through_delta = 0, joined = 0, light_sampled = 0;
};

// Calls f(x, s, t, light, camera, camera_part, sample) for every path bdpt's
// subpaths make that a strategy (s, t) could join and that carries light;
// the subpaths' partial sums are for heuristic h and `merging`.
template <class F>
void for_each_path(const Scene& scene, int samples, MisHeuristic h, const Merging& merging, F&& f) {
  auto sampler = make_sampler();
  const PathSettings settings{8, 5, 0.95f, 0.1f, false};
  const Film& film = *scene.sensor().film();
  std::vector<PathVertex> camera, light;
  for (int i = 0; i < samples; ++i) {
    sampler->start_sample(SampleKey::camera({i % film.width(), i / film.width() % film.height()}), uint64_t(i), 7);
    const Vec2 raster{sampler->next_1d() * film.width(), sampler->next_1d() * film.height()};
    trace_camera_subpath(scene, scene.sensor().generate_ray(raster, sampler->next_2d()), *sampler, settings, camera);
    compute_densities(scene, camera, h, merging);
    trace_light_subpath(scene, *sampler, 0, settings, light);
    compute_densities(scene, light, h, merging);
    for (int t = 1; t <= int(camera.size()); ++t)
      for (int s = 0; s <= int(light.size()); ++s) {
        if (s + t < 2 || s + t - 1 > 8) continue;
        if (s == 0 && (t < 2 || !(camera[t - 1].emitter || camera[t - 1].environment))) continue;
        std::vector<PathVertex> camera_part(camera.begin(), camera.begin() + t);
        if (s == 0 && camera_part.back().environment) camera_part.back().emitter = scene.infinite_emitters()[0];
        const std::vector<PathVertex> x = join(light, camera_part, s, t);
        if (!possible(x, s) || !carries_light(scene, x, s)) continue;
        f(x, s, t, light, camera, camera_part, i);
      }
  }
}

void check_scene(const Scene& scene, MisHeuristic h, int samples, Tally& tally) {
  for_each_path(scene, samples, h, {},
                [&](const std::vector<PathVertex>& x, int s, int t, const std::vector<PathVertex>& light,
                    const std::vector<PathVertex>& camera, const std::vector<PathVertex>& camera_part, int i) {
                  const int k = s + t - 1;
                  double sum = 0;
                  for (int sp = 0; sp <= k; ++sp)
                    if (possible(x, sp)) sum += recomputed_weight(scene, x, sp, h);
                  const float own = strategy_weight(scene, std::span(light).first(s), camera_part, s, t, h);
                  // bdpt's own route for s, t >= 2: the densities from the ends' joint evaluation.
                  if (s >= 2 && t >= 2 && joinable(light[s - 1]) && joinable(camera[t - 1])) {
                    const PathVertex &cv = camera[t - 1], &lv = light[s - 1];
                    const Vec3 w = direction_to(cv, lv);
                    const ScatteringBothWays at_camera = scattering_both_ways(cv, direction_to(cv, camera[t - 2]), w);
                    const ScatteringBothWays at_light = scattering_both_ways(lv, direction_to(lv, light[s - 2]), -w);
                    const float joined =
                        strategy_weight(std::span(light).first(s), camera_part, s, t, h,
                                        joined_densities(camera[t - 2], cv, at_camera, light[s - 2], lv, at_light));
                    ASSERT_EQ(joined, own) << "strategy (" << s << ", " << t << ") of sample " << i;
                    ++tally.joined;
                  }
                  // Its route for s = 1: a point sampled on an emitter.
                  if (s == 1 && t >= 2 && joinable(camera[t - 1])) {
                    const PathVertex& cv = camera[t - 1];
                    const ScatteringBothWays at_camera =
                        scattering_both_ways(cv, direction_to(cv, camera[t - 2]), direction_to(cv, light[0]));
                    const float sampled =
                        strategy_weight(std::span(light).first(1), camera_part, 1, t, h,
                                        light_sample_densities(scene, camera[t - 2], cv, at_camera, light[0]));
                    ASSERT_EQ(sampled, own) << "strategy (1, " << t << ") of sample " << i;
                    ++tally.light_sampled;
                  }
                  const float fresh = recomputed_weight(scene, x, s, h);
                  ++tally.paths;
                  tally.environment += x[0].environment && !delta_light(x[0]);
                  tally.point_light += !x[0].environment && delta_light(x[0]);
                  tally.directional += x[0].environment && delta_light(x[0]);
                  tally.through_delta += std::any_of(x.begin(), x.end(), [](const PathVertex& v) { return v.delta; });
                  ASSERT_NEAR(sum, 1, 1e-3) << "strategy (" << s << ", " << t << ") of sample " << i;
                  ASSERT_NEAR(own, fresh, 1e-3) << "strategy (" << s << ", " << t << ") of sample " << i;
                });
}

TEST(StrategyWeight, WeightsOfEveryPathSumToOne) {
  const auto glass = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml", {{"res", "16"}});
  const auto mixed = test::scene_from_xml(kMixedScene);
  const auto sun = test::scene_from_xml(sun_scene());
  for (const MisHeuristic h : {MisHeuristic::Power, MisHeuristic::Balance}) {
    Tally tally;
    check_scene(*glass, h, 1000, tally);
    check_scene(*mixed, h, 1000, tally);
    check_scene(*sun, h, 1000, tally);
    // Enough paths of every kind were seen for the test to mean something.
    EXPECT_GT(tally.paths, 5000);
    EXPECT_GT(tally.environment, 100);
    EXPECT_GT(tally.point_light, 100);
    EXPECT_GT(tally.directional, 100);
    EXPECT_GT(tally.through_delta, 100);
    EXPECT_GT(tally.joined, 1000);
    EXPECT_GT(tally.light_sampled, 1000);
    std::printf(
        "%d paths: %d from the environment, %d from point lights, %d from the sun, %d through delta lobes; %d and "
        "%d weighed from joint evaluations (s, t >= 2; s = 1)\n",
        tally.paths, tally.environment, tally.point_light, tally.directional, tally.through_delta, tally.joined,
        tally.light_sampled);
  }
}

// With vertex merging (vcm) every interior vertex on a non-delta surface
// is one more strategy: the weights of the connections used and of the
// merges sum to one over every path, with connections (vcm's both mode) and
// without (its merge mode, where only s = 0 and the merges remain). With
// the balance heuristic a merge's weight is its density's share, so its
// ratio to connection s = i + 1's is the camera subpath's density of x_i
// times eta, that density computed afresh; where x_{i+1} scatters through a
// delta lobe, connection s = i + 1 is impossible and the camera's density
// of x_i is the delta's, so the merge's ratio to connection s = i's is the
// light subpath's density of x_i times eta. With merges after delta lobes
// only, a merge at x_i is a strategy where x_{i+1} scatters through one.
TEST(StrategyWeight, WithMergesWeightsOfEveryPathSumToOne) {
  const auto glass = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml", {{"res", "16"}});
  const auto mixed = test::scene_from_xml(kMixedScene);
  // The floor in smooth plastic, so that many paths leave it through the coat.
  std::string coated_xml = kMixedScene;
  const std::string floor = "<bsdf type='diffuse'/></shape>";
  coated_xml.replace(coated_xml.find(floor), floor.size(), "<bsdf type='plastic'/></shape>");
  const auto coated = test::scene_from_xml(coated_xml);
  int paths = 0, merges = 0, ratios = 0, delta_ratios = 0, through_coat = 0, after_delta = 0, ends_left_delta = 0;
  for (const MisHeuristic h : {MisHeuristic::Power, MisHeuristic::Balance})
    for (const Merging merging : {Merging{0.05f, true}, Merging{2.0f, true}, Merging{0.05f, false},
                                  Merging{0.05f, true, true}, Merging{2.0f, true, true}})
      for (const Scene* scene : {glass.scene.get(), mixed.scene.get(), coated.scene.get()})
        for_each_path(*scene, 1000, h, merging,
                      [&](const std::vector<PathVertex>& x, int s, int t, const std::vector<PathVertex>& light,
                          const std::vector<PathVertex>&, const std::vector<PathVertex>& camera_part, int sample) {
                        const int k = s + t - 1;
                        // The strategy's weight from its subpaths as they were traced (an end they left through
                        // a delta lobe, which the connection scatters through its other lobes, included) is the
                        // one computed afresh from the path.
                        if (merging.connections || s == 0) {
                          const std::span<const PathVertex> part = std::span(light).first(size_t(s));
                          const float own =
                              strategy_weight(part, camera_part, s, t, h,
                                              connection_densities(*scene, part, camera_part, s, t), merging);
                          ASSERT_NEAR(own, recomputed_weight(*scene, x, s, h, merging), 1e-3)
                              << "strategy (" << s << ", " << t << ") of sample " << sample;
                          ends_left_delta += (s >= 1 && light[size_t(s - 1)].delta) || camera_part.back().delta;
                        }
                        double sum = 0;
                        for (int sp = 0; sp <= k; ++sp)
                          if (possible(x, sp) && (merging.connections || sp == 0))
                            sum += recomputed_weight(*scene, x, sp, h, merging);
                        for (int i = 1; i < k; ++i) {
                          if (mergeable(x[i]) && x[i].delta) ++through_coat;
                          if (!mergeable(x[i]) || x[i].delta) continue;
                          if (merging.after_delta_only && (i + 1 == k || !x[i + 1].delta)) continue;
                          const float w = recomputed_merge_weight(*scene, x, i, h, merging);
                          sum += w;
                          ++merges;
                          after_delta += merging.after_delta_only;
                          if (h != MisHeuristic::Balance || !merging.connections) continue;
                          if (x[i + 1].delta) {
                            if (!possible(x, i)) continue;
                            const float expected = light_density(*scene, x, i) * merging.eta;
                            ASSERT_NEAR(w / recomputed_weight(*scene, x, i, h, merging), expected, 1e-3 * expected)
                                << "merge at x_" << i << " before a delta lobe, strategy (" << s << ", " << t
                                << ") of sample " << sample;
                            ++delta_ratios;
                            continue;
                          }
                          if (!possible(x, i + 1)) continue;
                          const float expected = camera_density(*scene, x, i) * merging.eta;
                          ASSERT_NEAR(w / recomputed_weight(*scene, x, i + 1, h, merging), expected, 1e-3 * expected)
                              << "merge at x_" << i << " of strategy (" << s << ", " << t << ") of sample " << sample;
                          ++ratios;
                        }
                        ++paths;
                        ASSERT_NEAR(sum, 1, 1e-3) << "strategy (" << s << ", " << t << ") of sample " << sample;
                      });
  EXPECT_GT(paths, 5000);
  EXPECT_GT(merges, 5000);
  EXPECT_GT(ratios, 1000);
  EXPECT_GT(delta_ratios, 100);
  // Vertices a merge cannot make: the path leaves them through the delta
  // coat of smooth plastic.
  EXPECT_GT(through_coat, 100);
  EXPECT_GT(after_delta, 500);
  EXPECT_GT(ends_left_delta, 100);
  std::printf(
      "%d paths, %d merges (%d of them after delta lobes only), %d merge-to-connection ratios checked (%d before a "
      "delta lobe), %d vertices left through a delta coat, %d connections at an end its subpath left so\n",
      paths, merges, after_delta, ratios, delta_ratios, through_coat, ends_left_delta);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

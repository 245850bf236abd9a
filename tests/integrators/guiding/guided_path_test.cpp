// guided_path as a render: the same image for any thread count, whatever
// range or replay renders a sample; path's image where it learns nothing or
// has not learnt yet; a closed emitting sphere's known radiance; the
// one-sample MIS weights against their definition; its parameters' errors.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/render/renderer.h"
#include "integrators/path/guiding/guided_radiance.h"
#include "integrators/path/path_tracing.h"
#include "tests/support/independent_runs.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;
using testing::Not;

const std::string kBox = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml";
// Low enough that a small image's records divide space into many regions,
// and guide wherever a region learnt anything.
const std::string kGuided = "guided_path:spatial_threshold=100,min_records=0";
const std::string kAlwaysGuided = kGuided + ",always_guide=true";

std::vector<float> render(const LoadedScene& scene, const std::string& integrator, uint32_t spp, int threads,
                          uint64_t first = 0, uint64_t seed = 3) {
  RenderSettings settings;
  settings.integrator = integrator;
  settings.spp = spp;
  settings.first_sample = first;
  settings.seed = seed;
  settings.threads = threads;
  settings.aovs = false;
  return RenderJob(scene, settings).run().film.resolve();
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(GuidedPath, IsBitIdenticalForAnyThreadCount) {
  const auto scene = load_scene(kBox, {{"res", "40"}});
  const auto one = render(scene, kGuided, 24, 1);
  EXPECT_TRUE(same_bits(one, render(scene, kGuided, 24, 2)));
  EXPECT_TRUE(same_bits(one, render(scene, kGuided, 24, 3)));
  EXPECT_FALSE(same_bits(one, render(scene, "path", 24, 2))) << "guiding changed nothing";
  const auto always = render(scene, kAlwaysGuided, 24, 1);
  EXPECT_TRUE(same_bits(always, render(scene, kAlwaysGuided, 24, 3)));
}

// A sample rendered alone (as the first of its range, or replayed) was
// drawn by the distributions the passes before it learnt, traced there for
// learning alone: with one sample per pixel the image holds its values.
TEST(GuidedPath, ASampleIsTheSameRenderedAloneOrReplayed) {
  const auto scene = load_scene(kBox, {{"res", "16"}, {"integrator", "guided_path"}});
  const auto alone = render(scene, "", 1, 2, 9);
  for (Vec2i p : {Vec2i{3, 4}, Vec2i{15, 0}, Vec2i{8, 12}}) {
    const auto replayed = replay_sample(*scene, *scene.integrator, p, 9, 3).values;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(replayed[c], alone[(p.y * 16 + p.x) * 3 + c]) << p.x << ", " << p.y;
  }
}

// Pass 0 samples by the BSDF alone; where nothing can be learnt (paths of
// two segments) no pass guides: path's image, bit for bit.
TEST(GuidedPath, IsPathWhereItHasNotLearnt) {
  const auto scene = load_scene(kBox, {{"res", "24"}});
  EXPECT_TRUE(same_bits(render(scene, kGuided, 1, 2), render(scene, "path", 1, 2)));
  const auto direct = load_scene(kBox, {{"res", "24"}, {"max_depth", "2"}, {"integrator", "guided_path"}});
  EXPECT_TRUE(same_bits(render(direct, "", 12, 2), render(direct, "path", 12, 2)));
  EXPECT_THAT(direct.integrator->plan(*direct.scene), HasSubstr("guiding skipped (max_depth 2 leaves no light"));
  // Where it can learn, the plan says which guides stay unguided.
  const auto box = load_scene(kBox, {{"res", "24"}});
  EXPECT_THAT(make_integrator("guided_path:min_records=77")->plan(*box.scene),
              HasSubstr("unguided, and where a guide learnt from fewer than 77 records"));
}

// On the box whose light hides above a baffle, guiding must pay: light
// paths teach the trees where the opening is, and roulette judges guided
// paths by their BSDF's weight, not by the mixture's (which would end them
// in proportion as the guide sends them toward the light). The variance of
// each integrator is estimated from two independent renders (half the mean
// squared difference over 64 x 64 x 3 values). With fixed seeds the ratio
// guided / path was 0.42 (seeds 1, 2) and 0.50 (3, 4); with a guide learnt
// from camera paths alone it was 1.26, with roulette on the mixture's
// weight 1.09. Adjoint-driven roulette is off, so that path's roulette
// judges every guided vertex here.
TEST(GuidedPath, HalvesThePathTracersVarianceWhereLightComesThroughAGap) {
  const auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-baffle.xml", {{"res", "64"}});
  const auto variance = [&](const std::string& integrator) {
    const auto a = render(scene, integrator, 256, 0, 0, 1), b = render(scene, integrator, 256, 0, 0, 2);
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += double(a[i] - b[i]) * double(a[i] - b[i]);
    return sum / double(a.size()) / 2;
  };
  const double path = variance("path"), guided = variance("guided_path:adjoint_roulette=0");
  EXPECT_LT(guided, 0.7 * path) << "guided " << guided << ", path " << path;
}

// The training passes judge whether guided samples cost less per unit of
// error than unguided ones. On the Cornell box, lit mostly directly, guided
// paths stay about twice as long in the box for a third less variance: it
// does not pay, and guiding stops (with seed 1 after pass 3; seeds 2 and 3
// after pass 2). Behind the baffle guiding cuts the variance
// tenfold and goes on. always_guide keeps it on regardless.
TEST(GuidedPath, StopsGuidingWhereItDoesNotPay) {
  const auto load = [](const std::string& scene_name) {
    return load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + scene_name + ".xml",
                      {{"res", "64"}, {"sampler", "independent"}});
  };
  const auto summary = [&](const std::string& scene_name, const std::string& integrator) {
    const auto scene = load(scene_name);
    RenderSettings settings;
    settings.integrator = integrator;
    settings.spp = 64;
    settings.seed = 1;
    settings.aovs = false;
    return RenderJob(scene, settings).run().stats.summary;
  };
  EXPECT_THAT(summary("cornell-box", "guided_path"), HasSubstr("guiding stopped after pass"));
  const std::string baffle = summary("cornell-box-baffle", "guided_path");
  EXPECT_THAT(baffle, Not(HasSubstr("stopped"))) << baffle;
  EXPECT_THAT(baffle, HasSubstr("pass 5: relative variance")) << baffle;
  EXPECT_THAT(baffle, HasSubstr("guides whose light samples reached no light")) << baffle;
  EXPECT_THAT(summary("cornell-box", "guided_path:always_guide=true"), Not(HasSubstr("stopped")));
  // Once stopped, a sample is path's, bit for bit.
  const auto box = load("cornell-box");
  EXPECT_TRUE(same_bits(render(box, "guided_path", 8, 2, 64, 1), render(box, "path", 8, 2, 64, 1)));
}

// What the camera sees directly is the same guided or not, so the payoff
// leaves it out: here every surface is black, the emitter in view has
// sharp edges across pixels, and all that varies is whether a camera ray
// lands on it. Both passes judged then read no variance at all; counted,
// the edge pixels' variance would read as some.
TEST(GuidedPath, PayoffLeavesOutWhatTheCameraSeesDirectly) {
  const std::string xml =
      "<scene version='3.0.0'><integrator type='guided_path'><integer name='training_passes' value='3'/>"
      "</integrator><sensor type='perspective'><float name='fov' value='40'/><sampler type='independent'/>"
      "<transform name='to_world'><lookat origin='0, 0, 4' target='0, 0, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
      "<rfilter type='box'/></film></sensor>"
      "<shape type='rectangle'><transform name='to_world'><rotate z='1' angle='20'/>"
      "<scale value='0.6'/></transform><bsdf type='diffuse'><rgb name='reflectance' value='0'/></bsdf>"
      "<emitter type='area'><rgb name='radiance' value='5'/></emitter></shape>"
      "<shape type='rectangle'><transform name='to_world'><scale value='5'/><translate z='-1'/></transform>"
      "<bsdf type='diffuse'><rgb name='reflectance' value='0'/></bsdf></shape></scene>";
  RenderSettings settings;
  settings.integrator = "guided_path";
  settings.spp = 16;
  settings.seed = 1;
  settings.aovs = false;
  const std::string summary = RenderJob(test::scene_from_xml(xml), settings).run().stats.summary;
  EXPECT_THAT(summary, HasSubstr("guiding stopped after pass 2 (relative variance 0 at")) << summary;
  EXPECT_THAT(summary, HasSubstr("against 0 at")) << summary;
}

// Inside a closed sphere emitting 1 and reflecting 0.5 every ray sees
// 1 / (1 - 0.5) = 2, however the directions are drawn. Its mean over 16
// independent runs (a pass's samples share the distribution they
// learnt, so runs give the error) of 16 spp at 16x16, by guided_path with
// `parameters` beside a spatial_threshold of 50 and always_guide.
constexpr int kSphereRuns = 16;
test::RegionEstimate closed_sphere(const std::string& parameters) {
  const std::string xml =
      "<scene version='3.0.0'><integrator type='guided_path'><float name='spatial_threshold' value='50'/>" +
      parameters +
      "<boolean name='always_guide' value='true'/></integrator><sensor type='perspective'><float name='fov' "
      "value='70'/><sampler type='independent'/>"
      "<transform name='to_world'><lookat origin='0.1, 0.2, 0' target='1, 0.3, 0.2'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
      "<rfilter type='box'/></film></sensor>"
      "<shape type='sphere'><boolean name='flip_normals' value='true'/>"
      "<bsdf type='diffuse'><rgb name='reflectance' value='0.5'/></bsdf>"
      "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>";
  return test::estimate_regions(test::scene_from_xml(xml), test::grid_regions(16, 16, 1), 16, kSphereRuns, 40)[0];
}

// Student's t at 0.1%.
TEST(GuidedPath, ClosedEmittingSphereShowsLeOverOneMinusAlbedo) {
  const auto estimate = closed_sphere("");
  const double t = (estimate.mean - 2) / estimate.standard_error;
  EXPECT_LT(std::abs(t), test::two_sided_t_critical(0.001, kSphereRuns - 1))
      << estimate.mean << " +- " << estimate.standard_error;
}

// The same sphere after two training passes, so that 13 of each pixel's
// 16 samples meet adjoint-driven roulette: every region learnt about 2
// (its emission and what it reflects), so a path's expected contribution
// is its weight w, and below the threshold it survives with probability
// w over the threshold (after two bounces w is about 0.25: 0.5 with the
// default 0.5, 0.25 with 1) and weighs that much more. Student's t at
// 0.1%, each.
TEST(GuidedPath, AdjointRouletteKeepsTheClosedSpheresLeOverOneMinusAlbedo) {
  for (const char* threshold : {"0.5", "1"}) {
    const auto estimate = closed_sphere(std::string("<integer name='training_passes' value='2'/><float "
                                                    "name='adjoint_roulette' value='") +
                                        threshold + "'/>");
    const double t = (estimate.mean - 2) / estimate.standard_error;
    EXPECT_LT(std::abs(t), test::two_sided_t_critical(0.001, kSphereRuns - 1))
        << "adjoint_roulette " << threshold << ": " << estimate.mean << " +- " << estimate.standard_error;
  }
}

// One-sample MIS with the balance heuristic: technique i (the BSDF with
// probability a, the learned distribution otherwise) weighs its sample by
// w_i = c_i p_i / (sum_j c_j p_j) and divides by c_i p_i; both come to f
// over the mixture's density, and the weights sum to one.
// Where a guide learnt that its light samples reach no light, its guided
// vertices take none, and the light their directions find counts in full
// instead of by MIS. Here every guide is told so in the Cornell box,
// whose light nearly every vertex sees, so that all its direct light
// comes from directions that hit the lamp: along a ray to the floor the
// guided walk's mean must still be path's. A z-test at 0.1% on 2^17
// independent samples of each; the guided samples' variance, several
// times path's, shows that they took no light samples.
TEST(GuidedPath, SkippedLightSamplesLeaveTheLightToTheDirections) {
  const auto loaded = load_scene(kBox, {{"res", "8"}});
  const Scene& scene = *loaded.scene;
  GuidingTree tree(scene.bounds());
  const Vec3 centre = scene.bounds().center();
  for (int b = 0; b < kNormalBuckets; ++b)
    for (int i = 0; i < 64; ++i) tree.region_at(centre).record(b, {(i % 8 + 0.5f) / 8, (i / 8 + 0.5f) / 8}, 1);
  GuidingRefinement uniform;
  uniform.spatial_threshold = 1e9;
  uniform.min_records = 0;
  tree.refine(uniform, 1);
  ASSERT_EQ(tree.regions(), 1u);
  for (DirectionalGuide& g : tree.region_at(centre).guides) {
    ASSERT_FALSE(g.sampling.empty());
    g.lights_unseen = true;
  }
  GuidedWalk walk;
  walk.guide = true;
  walk.skip_unseen_lights = true;
  const PathSettings settings;
  const Ray ray{centre, normalize(Vec3(0.2f, -1, 0.1f))};
  const auto moments = [&](auto&& trace, uint64_t seed) {
    auto sampler = test::make_sampler("independent");
    double sum = 0, squares = 0;
    constexpr int kSamples = 1 << 17;
    for (int i = 0; i < kSamples; ++i) {
      sampler->start_sample(SampleKey::camera({0, 0}), uint64_t(i), seed);
      const Color L = trace(*sampler);
      const double y = (L.r + L.g + L.b) / 3;
      sum += y;
      squares += y * y;
    }
    const double mean = sum / kSamples;
    return std::pair{mean, (squares / kSamples - mean * mean) / kSamples};
  };
  const auto [path_mean, path_variance] = moments([&](Sampler& s) { return trace_path(scene, ray, s, settings); }, 1);
  const auto [guided_mean, guided_variance] =
      moments([&](Sampler& s) { return trace_guided_path(scene, ray, s, settings, tree, walk, nullptr).L; }, 2);
  const double z = (guided_mean - path_mean) / std::sqrt(path_variance + guided_variance);
  EXPECT_LT(std::abs(z), test::two_sided_z_critical(0.001)) << guided_mean << " against path's " << path_mean;
  EXPECT_GT(guided_variance, 3 * path_variance);
}

TEST(GuidedPath, OneSampleMisWeightsAreTheBalanceHeuristics) {
  for (float a : {0.1f, 0.5f, 0.9f, 1.0f})
    for (float p_bsdf : {0.0f, 0.05f, 0.3f, 7.0f})
      for (float p_square : {0.0f, 0.5f, 3.0f, 40.0f}) {
        const double p_guide = p_square / (4 * M_PI);
        const double c_bsdf = a, c_guide = 1 - a;
        const double sum = c_bsdf * p_bsdf + c_guide * p_guide;
        if (!(sum > 0)) continue;
        const double w_bsdf = c_bsdf * p_bsdf / sum, w_guide = c_guide * p_guide / sum;
        EXPECT_NEAR(w_bsdf + w_guide, 1, 1e-12);
        const float mixture = mixture_pdf(a, p_bsdf, p_square);
        EXPECT_NEAR(mixture, sum, 1e-6 * sum);
        if (p_bsdf > 0) {
          EXPECT_NEAR(w_bsdf / (c_bsdf * p_bsdf), 1 / mixture, 1e-5 / mixture);
        }
        if (a < 1 && p_guide > 0) {
          EXPECT_NEAR(w_guide / (c_guide * p_guide), 1 / mixture, 1e-5 / mixture);
        }
      }
}

TEST(GuidedPath, VerticesWithDeltaLobesAreNotGuided) {
  EXPECT_TRUE(guidable(kDiffuseReflection));
  EXPECT_TRUE(guidable(kGlossyReflection | kGlossyTransmission));
  EXPECT_FALSE(guidable(kDeltaReflection | kDeltaTransmission));
  EXPECT_FALSE(guidable(kDiffuseReflection | kDeltaReflection));  // a smooth coating over a diffuse base
  EXPECT_FALSE(guidable(kNull));
}

std::string with_parameter(const std::string& declaration) {
  return "<scene version='3.0.0'>\n<integrator type='guided_path'>\n" + declaration + "\n</integrator>\n</scene>";
}

TEST(GuidedPath, BadParametersNameThemselves) {
  const struct {
    std::string declaration, message;
  } cases[] = {
      {"<integer name='training_passes' value='0'/>",
       "'training_passes' of integrator 'guided_path': must be between 1 and 20"},
      {"<string name='always_guide' value='yes'/>",
       "parameter 'always_guide' of integrator 'guided_path' must be boolean, not string"},
      {"<integer name='training_passes' value='-2'/>",
       "'training_passes' of integrator 'guided_path': must be between 1 and 20"},
      {"<integer name='training_passes' value='21'/>",
       "'training_passes' of integrator 'guided_path': must be between 1 and 20"},
      {"<float name='bsdf_fraction' value='0'/>",
       "'bsdf_fraction' of integrator 'guided_path': must be in (0, 1]: with 0, directions"},
      {"<float name='bsdf_fraction' value='1.5'/>", "'bsdf_fraction' of integrator 'guided_path': must be in (0, 1]"},
      {"<float name='spatial_threshold' value='-1'/>",
       "'spatial_threshold' of integrator 'guided_path': must be positive"},
      {"<float name='directional_threshold' value='1'/>",
       "'directional_threshold' of integrator 'guided_path': must be in (0, 1)"},
      {"<integer name='max_tree_memory' value='0'/>",
       "'max_tree_memory' of integrator 'guided_path': must be between 1 and 1048576 (MiB)"},
      {"<integer name='min_records' value='-1'/>",
       "'min_records' of integrator 'guided_path': must be between 0 and 1000000000 (records a guide needs"},
      {"<float name='light_paths' value='-1'/>",
       "'light_paths' of integrator 'guided_path': must be between 0 and 1024 (light paths per camera sample"},
      {"<float name='light_paths' value='2000'/>",
       "'light_paths' of integrator 'guided_path': must be between 0 and 1024"},
      {"<float name='adjoint_roulette' value='-0.1'/>",
       "'adjoint_roulette' of integrator 'guided_path': must be in [0, 1]: the share of its first vertex's"},
      {"<float name='adjoint_roulette' value='1.5'/>",
       "'adjoint_roulette' of integrator 'guided_path': must be in [0, 1]"},
  };
  for (const auto& c : cases) {
    const std::string error = test::load_error(with_parameter(c.declaration), "guided.xml");
    EXPECT_THAT(error, HasSubstr("guided.xml:3")) << c.declaration;
    EXPECT_THAT(error, HasSubstr(c.message)) << c.declaration;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

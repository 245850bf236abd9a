// The render job: integrator overrides keep the scene's shared settings,
// and renders of disjoint sample ranges merge into the render of their
// union.

#include "core/job/render_job.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

#include "core/job/range_merge.h"
#include "core/job/render_outputs.h"
#include "core/loader/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;
using testing::StartsWith;

LoadedScene scene_with(const std::string& integrator) {
  return test::scene_from_xml(
      "<scene version='3.0.0'>" + integrator +
      "<shape type='sphere'><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>");
}

std::string described(const std::string& scene_integrator, const std::string& override_spec) {
  RenderSettings settings;
  settings.integrator = override_spec;
  return RenderJob(scene_with(scene_integrator), settings).integrator().describe();
}

TEST(RenderJob, AnOverrideKeepsTheSettingsTheScenesIntegratorShares) {
  const std::string path =
      "<integrator type='path'><integer name='max_depth' value='65'/>"
      "<boolean name='hide_emitters' value='true'/></integrator>";
  EXPECT_THAT(described(path, "bdpt"), StartsWith("bdpt max_depth=65 rr_depth=1"));
  EXPECT_THAT(described(path, "bdpt"), HasSubstr("hide_emitters=true"));
  EXPECT_THAT(described(path, "bdpt:max_depth=4"), StartsWith("bdpt max_depth=4 "));
  EXPECT_THAT(described(path, "ptracer:rr_depth=2"), StartsWith("ptracer max_depth=65 rr_depth=2"));
  // direct declares no max_depth: nothing to keep, and no error.
  EXPECT_THAT(described(path, "direct"), StartsWith("direct emitter_samples=1"));
  const std::string photon = "<integrator type='photon'><integer name='photons' value='1234'/></integrator>";
  EXPECT_THAT(described(photon, "sppm"), HasSubstr("photons=1234"));
  EXPECT_THAT(described(photon, "sppm:photons=99"), HasSubstr("photons=99 "));
  // bdpt's light subpaths and sppm's photons roulette from the first bounce
  // unless the scene says otherwise.
  EXPECT_THAT(described(path, "sppm"), StartsWith("sppm max_depth=65 rr_depth=1 "));
  EXPECT_THAT(described("<integrator type='path'><integer name='rr_depth' value='5'/></integrator>", "sppm"),
              StartsWith("sppm max_depth=-1 rr_depth=5 "));
  EXPECT_THAT(described("", "bdpt"), StartsWith("bdpt max_depth=-1"));
  EXPECT_THAT(described(path, ""), StartsWith("path max_depth=65"));
}

// An integrator with nothing to say of its own (direct) leaves the
// transport's line alone, not after an empty line.
TEST(RenderJob, APlanWithoutTheIntegratorsLineStartsWithTheTransport) {
  const auto plan = [](const std::string& integrator) {
    RenderSettings settings;
    settings.integrator = integrator;
    return RenderJob(load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-spectral.xml", {{"res", "8"}}),
                     settings)
        .plan();
  };
  EXPECT_THAT(plan("direct"), StartsWith("spectral transport: yes"));
  EXPECT_THAT(plan("path"), StartsWith("path: "));
  EXPECT_THAT(plan("path"), HasSubstr("\nspectral transport: yes"));
}

const std::string kGlass = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml";

RenderFile render_range(const LoadedScene& scene, const std::string& integrator, uint64_t first, uint32_t spp,
                        uint64_t seed = 7) {
  RenderSettings settings;
  settings.integrator = integrator;
  settings.first_sample = first;
  settings.spp = spp;
  settings.seed = seed;
  const RenderJob job(scene, settings);
  const RenderResult r = job.run();
  const std::optional<FirstHitLayers> first_hit = job.first_hit_layers(r);
  return {"range " + std::to_string(first) + "+" + std::to_string(spp),
          RenderLayers(r.film, first_hit ? &*first_hit : nullptr, r.stats.variance_known, true).image(),
          render_metadata(job, r, "glass", true)};
}

// Whether a channel holds part of a raw sum's remainder (ExactSum::rest).
bool remainder_part(const std::string& channel) {
  return channel.rfind("raw.", 0) == 0 && channel.find_last_of("345") == channel.size() - 1 &&
         channel[channel.size() - 2] == '.';
}

// Whether a channel comes from the variance's moments, plain double sums
// (FilmBuffer::MomentSums) that merges reproduce only to rounding.
bool moment_channel(const std::string& channel) {
  return channel.rfind("variance.", 0) == 0 || channel.rfind("raw.weight2.", 0) == 0 ||
         channel.rfind("raw.w2x", 0) == 0;
}

// Whether two images of the same channels are identical bit for bit, raw
// sums included but for their remainders (where a pixel's terms span more
// than 2^52, as bdpt's splats can, the order of the terms shows there,
// though never in an image value) and for the moments' channels; returns
// the largest relative difference between their variance layers.
double moments_difference(const Image& a, const Image& b, bool* identical) {
  EXPECT_EQ(a.channels, b.channels);
  double largest = 0;
  *identical = true;
  for (size_t c = 0; c < a.channels.size(); ++c) {
    if (remainder_part(a.channels[c])) continue;
    for (size_t p = 0; p < a.pixels.size() / a.channels.size(); ++p) {
      const float x = a.pixels[p * a.channels.size() + c], y = b.pixels[p * b.channels.size() + c];
      if (a.channels[c].rfind("variance.", 0) == 0)
        largest = std::max(largest, std::abs(double(x) - y) / std::max(1e-30, std::abs(double(y))));
      else if (!moment_channel(a.channels[c]))
        *identical = *identical && std::memcmp(&x, &y, sizeof x) == 0;
    }
  }
  return largest;
}

// Bit for bit, raw sums' values included (the beauty's sums are exact),
// but for the variance, whose moments are plain doubles; photon too, whose photon rounds follow the sample index rather
// than the render's own passes; the ranges split passes.
TEST(RenderJob, DisjointSampleRangesMergeIntoTheRenderOfTheirUnion) {
  for (const char* sampler : {"independent", "ldsampler", "stratified", "multijitter", "halton"})
    for (const char* integrator :
         {"path", "photon:photons=3000", "bdpt", "ptracer", "guided_path:spatial_threshold=100"}) {
      const auto scene = load_scene(kGlass, {{"res", "24"}, {"sampler", sampler}});
      const RenderFile whole = render_range(scene, integrator, 0, 21);
      const RenderFile merged =
          merge_sample_ranges({render_range(scene, integrator, 13, 8), render_range(scene, integrator, 0, 5),
                               render_range(scene, integrator, 5, 8)});
      bool identical = false;
      const double moments = moments_difference(merged.image, whole.image, &identical);
      EXPECT_TRUE(identical) << sampler << ", " << integrator;
      EXPECT_LE(moments, 1e-6) << sampler << ", " << integrator;
      EXPECT_EQ(merged.metadata.at("caustica:spp"), "21") << integrator;
      EXPECT_EQ(merged.metadata.at("caustica:ranges"), "0-20") << integrator;
    }
}

// A merge with a gap keeps its ranges, so it merges with what fills the
// gap and refuses what overlaps either part.
TEST(RenderJob, MergesWithGapsKeepTheirRanges) {
  const auto scene = load_scene(kGlass, {{"res", "8"}});
  RenderFile gap = merge_sample_ranges({render_range(scene, "path", 10, 5), render_range(scene, "path", 0, 5)});
  gap.path = "gap";
  EXPECT_EQ(gap.metadata.at("caustica:ranges"), "0-4,10-14");
  EXPECT_EQ(gap.metadata.at("caustica:first_sample"), "0");
  EXPECT_EQ(gap.metadata.at("caustica:spp"), "10");
  const RenderFile filled = merge_sample_ranges({gap, render_range(scene, "path", 5, 5)});
  EXPECT_EQ(filled.metadata.at("caustica:ranges"), "0-14");
  bool identical = false;
  moments_difference(filled.image, render_range(scene, "path", 0, 15).image, &identical);
  EXPECT_TRUE(identical);
  try {
    merge_sample_ranges({gap, render_range(scene, "path", 12, 2)});
    ADD_FAILURE() << "overlap with the second interval accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("overlaps the sample range of 'gap' (samples 12 to 13 against 10 to 14)"));
  }
}

// sppm's per-pixel statistics make iteration N of a render that starts at N
// another estimate: it refuses to start anywhere but at 0.
TEST(RenderJob, IterativeIntegratorsRenderFromTheFirstIterationOnly) {
  RenderSettings settings;
  settings.integrator = "sppm:photons=100";
  settings.first_sample = 3;
  settings.spp = 2;
  try {
    RenderJob(load_scene(kGlass, {{"res", "8"}}), settings).run();
    ADD_FAILURE() << "sppm rendered from iteration 3";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("renders from iteration 0 on, not from --first-sample 3"));
  }
}

TEST(RenderJob, RangeMergeRefusesOverlapsOtherSeedsAndMissingSums) {
  const auto scene = load_scene(kGlass, {{"res", "8"}});
  const RenderFile a = render_range(scene, "path", 0, 4), b = render_range(scene, "path", 3, 4);
  try {
    merge_sample_ranges({a, b});
    ADD_FAILURE() << "overlap accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("'range 3+4' overlaps the sample range of 'range 0+4' (samples 3 to 6 against 0 "
                                    "to 3)"));
  }
  try {
    merge_sample_ranges({a, render_range(scene, "path", 4, 4, 8)});
    ADD_FAILURE() << "other seed accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("has another seed than 'range 0+4'"));
  }
  try {
    merge_sample_ranges({a, without_raw_sums(render_range(scene, "path", 4, 4))});
    ADD_FAILURE() << "missing sums accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("holds no raw sums (render it with --raw-sums)"));
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

#include "core/film/film_buffer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/film/reconstruction_filter.h"
#include "core/film/splat_list.h"
#include "core/registry/properties.h"
#include "tests/support/test_scenes.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

TEST(FilmBuffer, WeightedMeanAndVariance) {
  FilmBuffer film(2, 1, {"R", "G", "B"});
  const float a[3] = {1, 2, 3}, b[3] = {3, 2, 1};
  film.add_sample({{1, 0}, 0}, a, 1);
  film.add_sample({{1, 0}, 1}, b, 3);
  const auto img = film.resolve();
  EXPECT_FLOAT_EQ(img[3], 2.5f);
  EXPECT_FLOAT_EQ(img[5], 1.5f);
  EXPECT_EQ(img[0], 0);  // a pixel without samples stays black
  const auto var = film.variance();
  // sum w^2 (x - mean)^2 / (sum w)^2 * n / (n - 1) = (2.25 + 9 * 0.25) / 16 * 2
  EXPECT_FLOAT_EQ(var[3], 0.5625f);
  EXPECT_EQ(film.sample_count({1, 0}), 2u);
}

// A film without moments (the first-hit layers') averages as one with
// them, and its raw sums carry the weighted sums, the weight and the count
// only; they add into another such film exactly.
TEST(FilmBuffer, AFilmWithoutMomentsKeepsMeansAndRawSumsOnly) {
  FilmBuffer with(2, 1, {"R", "G", "B", "Z"}), without(2, 1, {"R", "G", "B", "Z"}, FilmBuffer::Moments::None);
  const float a[4] = {1, 2, 3, 0.1f}, b[4] = {3, 2, 1, 7};
  for (FilmBuffer* film : {&with, &without}) {
    film->add_sample({{1, 0}, 0}, a, 1);
    film->add_sample({{1, 0}, 1}, b, 3);
  }
  EXPECT_TRUE(with.keeps_moments());
  EXPECT_FALSE(without.keeps_moments());
  EXPECT_EQ(without.resolve(), with.resolve());
  EXPECT_FLOAT_EQ(without.resolve()[7], (0.1f + 3 * 7) / 4);
  EXPECT_EQ(without.sample_count({1, 0}), 2u);
  EXPECT_THROW(without.variance(), std::logic_error);
  const std::vector<std::string> names = without.raw_channels("p.");
  ASSERT_EQ(names.size(), (4 + 1) * 6 + 1u);
  EXPECT_EQ(names[24], "p.weight.0");
  EXPECT_EQ(names.back(), "p.count");
  FilmBuffer merged(2, 1, {"R", "G", "B", "Z"}, FilmBuffer::Moments::None);
  merged.add_raw(without.export_raw(), 0);
  merged.add_raw(without.export_raw(), 0);
  EXPECT_EQ(merged.resolve(), with.resolve());
  EXPECT_EQ(merged.sample_count({1, 0}), 4u);
}

TEST(FilmBuffer, NonFiniteSamplesAreDroppedAndCounted) {
  FilmBuffer film(4, 4, {"R", "G", "B"});
  const float good[3] = {1, 1, 1}, nan[3] = {1, NAN, 1}, inf[3] = {INFINITY, 0, 0};
  film.add_sample({{2, 3}, 0}, good, 1);
  film.add_sample({{2, 3}, 7}, nan, 1);
  film.add_sample({{1, 1}, 4}, inf, 1);
  film.add_sample({{0, 0}, 0}, good, NAN);
  EXPECT_EQ(film.dropped_samples(), 3u);
  EXPECT_EQ(film.first_dropped().pixel, (Vec2i{0, 0}));
  const auto img = film.resolve();
  for (float v : img) EXPECT_TRUE(std::isfinite(v));
  EXPECT_FLOAT_EQ(img[(3 * 4 + 2) * 3 + 1], 1.0f);
}

// A constant environment seen by every camera ray: whatever the filter, the
// resolved image equals the radiance exactly.
TEST(FilmBuffer, ConstantImageStaysConstant) {
  for (const char* filter : {"box", "tent", "gaussian"}) {
    const auto scene = test::scene_from_xml(
        std::string("<scene version='3.0.0'><emitter type='constant'><rgb name='radiance' value='0.25, 0.5, 2'/>"
                    "</emitter><sensor type='perspective'><film type='hdrfilm'><integer name='width' value='9'/>"
                    "<integer name='height' value='7'/><rfilter type='") +
        filter + "'/></film></sensor></scene>");
    const auto img = test::render_scene(scene, 5).resolve();
    for (size_t i = 0; i < img.size(); i += 3) {
      EXPECT_FLOAT_EQ(img[i], 0.25f) << filter;
      EXPECT_FLOAT_EQ(img[i + 1], 0.5f) << filter;
      EXPECT_FLOAT_EQ(img[i + 2], 2.0f) << filter;
    }
  }
}

std::shared_ptr<ReconstructionFilter> make_filter(const char* name) {
  const PluginInfo* info = Registry::instance().find("rfilter", name);
  return std::dynamic_pointer_cast<ReconstructionFilter>(info->create(Properties(*info, {"test", 1})));
}

// A box filter puts a splat in the pixel it falls in; the image divides
// splats by the light paths per pixel.
TEST(FilmBuffer, BoxSplatLandsInItsPixel) {
  FilmBuffer film(4, 3, {"R", "G", "B"});
  film.enable_splats();
  SplatList list;
  list.add({2.3f, 1.7f}, Color(1, 2, 3));
  film.add_splats(list, *make_filter("box"), 0, 3);
  film.add_splat_paths(4);
  const auto img = film.resolve();
  for (size_t p = 0; p < 12; ++p) EXPECT_FLOAT_EQ(img[p * 3 + 1], p == 1 * 4 + 2 ? 0.5f : 0.0f) << "pixel " << p;
}

// Wider filters spread a splat over their reach with weights f(dx) f(dy)
// normalised by the filter's integral: summed over the pixels they make one
// on average over where the splat falls (exactly for the tent, whose
// integer translates sum to one). Rows outside the range given are left
// for another call.
TEST(FilmBuffer, SplatWeightsSumToOneOnAverage) {
  for (const char* name : {"tent", "gaussian"}) {
    const auto filter = make_filter(name);
    FilmBuffer film(12, 12, {"R", "G", "B"});
    film.enable_splats();
    SplatList list;
    constexpr int n = 16;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) list.add({5 + (i + 0.5f) / n, 6 + (j + 0.5f) / n}, Color(1));
    film.add_splats(list, *filter, 0, 6);
    film.add_splats(list, *filter, 6, 12);
    film.add_splat_paths(n * n);
    double sum = 0;
    for (float v : film.resolve()) sum += v;
    EXPECT_NEAR(sum, 3.0, 3e-3) << name;  // the filter's tabulated integral is good to 1e-3

    FilmBuffer top(12, 12, {"R", "G", "B"});
    top.enable_splats();
    top.add_splats(list, *filter, 0, 6);
    top.add_splat_paths(1);
    const auto img = top.resolve();
    for (size_t i = 6 * 12 * 3; i < img.size(); ++i) EXPECT_EQ(img[i], 0) << name;
  }
}

// Films packed in one process and added in another, or added in one, make
// the film of all their samples, splats and dropped samples, bit for bit
// but for the variance's moments (plain doubles, equal to rounding); a
// film without splats adds to one with them; a film of another shape is
// refused; a cleared film holds nothing.
TEST(FilmBuffer, PackedFilmsAddUpToTheFilmOfAllTheirSamples) {
  const auto gaussian = make_filter("gaussian");
  FilmBuffer whole(3, 2, {"R", "G", "B"}), a(3, 2, {"R", "G", "B"}), b(3, 2, {"R", "G", "B"});
  for (FilmBuffer* film : {&whole, &a}) {
    film->enable_splats();
    SplatList list;
    list.add({1.2f, 0.7f}, Color(0.3f, 1e-9f, 7));
    film->add_splats(list, *gaussian, 0, 2);
    film->add_splat_paths(3);
  }
  const float x[3] = {0.1f, 2, 3e5f}, y[3] = {1e-7f, 0.5f, 4}, bad[3] = {1, NAN, 0};
  for (uint64_t i = 0; i < 20; ++i) {
    FilmBuffer& part = i % 3 == 0 ? a : b;
    for (FilmBuffer* film : {&whole, &part}) {
      film->add_sample({{int(i % 3), int(i % 2)}, i}, i % 2 ? x : y, 0.25f + float(i) * 0.1f);
      if (i == 7 || i == 9) film->add_sample({{2, 1}, i}, bad, 1);
    }
  }
  // The exported sums but the moments'.
  const auto exact_sums = [names = whole.raw_channels("")](const FilmBuffer& film) {
    const std::vector<float> raw = film.export_raw();
    std::vector<float> out;
    for (size_t i = 0; i < raw.size(); ++i) {
      const std::string& name = names[i % names.size()];
      if (name.rfind("weight2.", 0) != 0 && name.rfind("w2x", 0) != 0) out.push_back(raw[i]);
    }
    return out;
  };
  const auto expect_variance_near = [&](const FilmBuffer& film) {
    const std::vector<float> got = film.variance(), want = whole.variance();
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-6 * want[i]) << i;
  };
  FilmBuffer merged(3, 2, {"R", "G", "B"});
  merged.add_packed(b.pack());
  merged.add_packed(a.pack());
  EXPECT_EQ(exact_sums(merged), exact_sums(whole));
  EXPECT_EQ(merged.resolve(), whole.resolve());
  expect_variance_near(merged);
  EXPECT_EQ(merged.dropped_samples(), 2u);
  EXPECT_EQ(merged.first_dropped().index, 7u);
  EXPECT_EQ(merged.sample_count({1, 1}), whole.sample_count({1, 1}));
  // The same in one process.
  FilmBuffer added(3, 2, {"R", "G", "B"});
  added.add(b);
  added.add(a);
  EXPECT_EQ(exact_sums(added), exact_sums(whole));
  EXPECT_EQ(added.resolve(), whole.resolve());
  expect_variance_near(added);
  EXPECT_EQ(added.dropped_samples(), 2u);
  EXPECT_EQ(added.first_dropped().index, 7u);
  added.clear();
  FilmBuffer empty(3, 2, {"R", "G", "B"});
  empty.enable_splats();  // which a cleared film keeps
  EXPECT_EQ(added.export_raw(), empty.export_raw());
  EXPECT_EQ(added.dropped_samples(), 0u);
  FilmBuffer other(4, 2, {"R", "G", "B"});
  EXPECT_THAT(test::thrown_message<std::invalid_argument>([&] { other.add_packed(a.pack()); }),
              HasSubstr("does not fit a film that takes"));
}

TEST(FilmBuffer, NonFiniteSplatsAreDroppedAndCounted) {
  FilmBuffer film(4, 4, {"R", "G", "B"});
  film.enable_splats();
  SplatList list;
  list.set_source({{3, 1}, 9});
  list.add({1.5f, 1.5f}, Color(NAN, 0, 0));
  list.set_source({{0, 2}, 4});
  list.add({1.5f, 1.5f}, Color(1));
  list.add({2.5f, 1.5f}, Color(0, INFINITY, 0));
  film.add_splats(list, *make_filter("box"), 0, 4);
  film.record_dropped(list);
  film.add_splat_paths(1);
  EXPECT_EQ(film.dropped_samples(), 2u);
  EXPECT_EQ(film.first_dropped().pixel, (Vec2i{3, 1}));
  EXPECT_EQ(film.first_dropped().index, 9u);
  const auto img = film.resolve();
  for (float v : img) EXPECT_TRUE(std::isfinite(v));
  EXPECT_FLOAT_EQ(img[(1 * 4 + 1) * 3], 1.0f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

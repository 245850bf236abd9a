#include "core/film/film_buffer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {

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
    const auto img = test::render_scene(*scene, 5).resolve();
    for (size_t i = 0; i < img.size(); i += 3) {
      EXPECT_FLOAT_EQ(img[i], 0.25f) << filter;
      EXPECT_FLOAT_EQ(img[i + 1], 0.5f) << filter;
      EXPECT_FLOAT_EQ(img[i + 2], 2.0f) << filter;
    }
  }
}

}  // namespace
}  // namespace caustica

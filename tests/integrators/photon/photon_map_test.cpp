// The photon map's radius query against brute force, over random photons
// (some in cells that share a hash bucket), and its independence of order.

#include "integrators/photon/photon_map.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <random>
#include <string>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::vector<Photon> random_photons(int n, uint32_t seed, float extent) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-extent, extent);
  std::vector<Photon> photons(n);
  for (int i = 0; i < n; ++i) {
    photons[i].p = {u(rng), u(rng), u(rng)};
    photons[i].depth = uint32_t(i);  // an id
  }
  return photons;
}

// Both maps answer random queries within `extent` alike, photon for photon
// and in the same order.
void expect_same_answers(const PhotonMap& a, const PhotonMap& b, uint32_t seed, float extent, int queries,
                         const std::string& what) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-extent, extent);
  for (int q = 0; q < queries; ++q) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    std::vector<uint32_t> from_a, from_b;
    a.for_each_within(p, [&](const Photon& ph) { from_a.push_back(ph.depth); });
    b.for_each_within(p, [&](const Photon& ph) { from_b.push_back(ph.depth); });
    EXPECT_EQ(from_a, from_b) << what << ", query " << q;
  }
}

TEST(PhotonMap, RadiusQueryFindsExactlyThePhotonsWithinReach) {
  // Few buckets for a wide spread of cells: many cells collide.
  const auto photons = random_photons(2000, 1, 5);
  const float radius = 0.4f;
  const PhotonMap map(photons, radius);
  EXPECT_EQ(map.size(), photons.size());
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(-5.5f, 5.5f);
  for (int q = 0; q < 300; ++q) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    std::vector<uint32_t> expected, found;
    for (const Photon& ph : photons)
      if (squared_length(ph.p - p) <= radius * radius) expected.push_back(ph.depth);
    map.for_each_within(p, [&](const Photon& ph) { found.push_back(ph.depth); });
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "query " << q;
  }
}

// Smaller radii than the map's (sppm's pixels), photons on shells just
// inside and outside the query sphere, where a cell culled by its distance
// from the query would lose them, near the origin and 10^4 radii from it.
TEST(PhotonMap, SmallerRadiiAndPhotonsAtTheSphereFindExactlyThoseWithinReach) {
  const float radius = 0.4f;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1, 1), shell(0.98f, 1.02f);
  for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{4e3f, -4e3f, 4e3f}})
    for (const float r : {radius, 0.5f * radius, 0.1f * radius}) {
      std::vector<Vec3> queries;
      std::vector<Photon> photons;
      for (int q = 0; q < 40; ++q) {
        queries.push_back(offset + Vec3{u(rng), u(rng), u(rng)});
        for (int k = 0; k < 50; ++k) {
          const Vec3 d = normalize(Vec3{u(rng), u(rng), u(rng)});
          Photon ph;
          ph.p = queries.back() + d * (r * shell(rng));
          ph.depth = uint32_t(photons.size());
          photons.push_back(ph);
        }
      }
      const PhotonMap map(photons, radius);
      for (const Vec3 p : queries) {
        std::vector<uint32_t> expected, found;
        for (const Photon& ph : photons)
          if (squared_length(ph.p - p) <= r * r) expected.push_back(ph.depth);
        map.for_each_within(p, r, [&](const Photon& ph) { found.push_back(ph.depth); });
        std::sort(found.begin(), found.end());
        EXPECT_EQ(found, expected) << "radius " << r << ", offset " << offset.x;
      }
    }
}

// A map rebuilt with other photons and another radius (as every round
// does) answers as a fresh map of them: nothing of the last round stays.
TEST(PhotonMap, RebuildingForgetsThePreviousPhotons) {
  const auto first = random_photons(3000, 4, 2), second = random_photons(500, 5, 3);
  PhotonMap reused(first, 0.5f);
  reused.build(second, 0.3f);
  const PhotonMap fresh(second, 0.3f);
  EXPECT_EQ(reused.size(), second.size());
  EXPECT_EQ(reused.radius(), 0.3f);
  expect_same_answers(reused, fresh, 6, 3, 200, "rebuilt");
}

// The map is built in parallel, chunk by chunk: photons that share a
// bucket must still come in the order they were stored (sums over them are
// then the same for any thread count), here across many chunks.
TEST(PhotonMap, PhotonsOfABucketKeepTheirOrderWhateverTheThreads) {
  std::vector<Photon> photons(70000);
  for (size_t i = 0; i < photons.size(); ++i) {
    photons[i].p = {0.25f, 0.25f, i % 2 ? 0.25f : 40.25f};  // two cells, both crowded
    photons[i].depth = uint32_t(i);
  }
  const auto shuffled = random_photons(50000, 8, 2);
  for (int threads : {1, 2, 5}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      const PhotonMap crowded(photons, 0.5f);
      std::vector<uint32_t> ids;
      crowded.for_each_within({0.25f, 0.25f, 0.25f}, [&](const Photon& ph) { ids.push_back(ph.depth); });
      ASSERT_EQ(ids.size(), photons.size() / 2) << threads;
      for (size_t k = 0; k < ids.size(); ++k) ASSERT_EQ(ids[k], 2 * k + 1) << threads << " threads, photon " << k;

      const PhotonMap map(shuffled, 0.2f);
      const PhotonMap one_thread = [&] {
        PhotonMap m;
        tbb::task_arena single(1);
        single.execute([&] { m.build(shuffled, 0.2f); });
        return m;
      }();
      expect_same_answers(map, one_thread, 9, 2, 100, std::to_string(threads) + " threads");
    });
  }
}

TEST(PhotonMap, EmptyMapAndNegativeCoordinates) {
  const PhotonMap empty(std::vector<Photon>{}, 1.0f);
  int calls = 0;
  empty.for_each_within({0, 0, 0}, [&](const Photon&) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::vector<Photon> photons(2);
  photons[0].p = {-0.05f, -0.05f, -0.05f};
  photons[1].p = {0.05f, 0.05f, 0.05f};
  const PhotonMap map(photons, 0.1f);
  map.for_each_within({0, 0, 0}, [&](const Photon&) { ++calls; });
  EXPECT_EQ(calls, 2);
  EXPECT_THROW(PhotonMap(photons, 0.0f), std::invalid_argument);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

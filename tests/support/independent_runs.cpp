#include "tests/support/independent_runs.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/image/image_input.h"
#include "tests/support/test_scenes.h"

namespace caustica::test {

std::vector<Region> grid_regions(int width, int height, int n) {
  std::vector<Region> regions;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      regions.push_back({{i * width / n, j * height / n}, {(i + 1) * width / n, (j + 1) * height / n}});
  return regions;
}

std::vector<RegionEstimate> estimate_regions(const LoadedScene& scene, const std::vector<Region>& regions, uint32_t spp,
                                             int runs, uint64_t first_seed, uint64_t* non_finite) {
  const int width = scene->sensor().film()->width();
  std::vector<double> sum(regions.size(), 0), sum2(regions.size(), 0);
  for (int r = 0; r < runs; ++r) {
    const FilmBuffer film = render_scene(scene, spp, first_seed + r);
    const auto img = film.resolve();
    if (non_finite) {
      *non_finite += film.dropped_samples();
      for (float v : img) *non_finite += !std::isfinite(v);
    }
    const size_t nc = img.size() / (size_t(width) * scene->sensor().film()->height());
    for (size_t i = 0; i < regions.size(); ++i) {
      double mean = 0;
      const Region& g = regions[i];
      for (int y = g.lo.y; y < g.hi.y; ++y)
        for (int x = g.lo.x; x < g.hi.x; ++x)
          for (int c = 0; c < 3; ++c) mean += img[(size_t(y) * width + x) * nc + c];
      mean /= 3.0 * (g.hi.x - g.lo.x) * (g.hi.y - g.lo.y);
      sum[i] += mean;
      sum2[i] += mean * mean;
    }
  }
  std::vector<RegionEstimate> out(regions.size());
  for (size_t i = 0; i < regions.size(); ++i) {
    const double mean = sum[i] / runs;
    const double variance = std::max(0.0, (sum2[i] - runs * mean * mean) / (runs - 1));
    out[i] = {mean, std::sqrt(variance / runs), runs};
  }
  return out;
}

bool seen_through_delta(const Scene& scene, const Region& g) {
  const float r = scene.sensor().film()->filter().radius();
  constexpr int kSteps = 6;
  for (int y = g.lo.y; y < g.hi.y; ++y)
    for (int x = g.lo.x; x < g.hi.x; ++x)
      for (int j = 0; j <= kSteps; ++j)
        for (int i = 0; i <= kSteps; ++i) {
          const Vec2 raster{x + 0.5f - r + 2 * r * i / kSteps, y + 0.5f - r + 2 * r * j / kSteps};
          const auto si = scene.intersect(scene.sensor().generate_ray(raster, {0.5f, 0.5f}));
          if (si && (si->shape->bsdf()->lobes() & kDelta)) return true;
        }
  return false;
}

std::vector<RegionEstimate> reference_regions(const std::string& name, const std::vector<Region>& regions) {
  const Image ref = read_image(std::string(CAUSTICA_SOURCE_DIR) + "/tests/data/references/" + name + ".exr");
  const auto channel = [&](const std::string& c) {
    return size_t(std::find(ref.channels.begin(), ref.channels.end(), c) - ref.channels.begin());
  };
  const size_t nc = ref.channels.size();
  const size_t rgb[3] = {channel("R"), channel("G"), channel("B")};
  const size_t var[3] = {channel("variance.R"), channel("variance.G"), channel("variance.B")};
  std::vector<RegionEstimate> out;
  for (const Region& g : regions) {
    double sum = 0, variance = 0;
    for (int y = g.lo.y; y < g.hi.y; ++y)
      for (int x = g.lo.x; x < g.hi.x; ++x) {
        const float* p = &ref.pixels[(size_t(y) * ref.width + x) * nc];
        double sigma = 0;
        for (int c = 0; c < 3; ++c) {
          sum += p[rgb[c]];
          sigma += std::sqrt(p[var[c]]);
        }
        variance += sigma * sigma / 9;
      }
    const double n = double(g.hi.x - g.lo.x) * (g.hi.y - g.lo.y);
    out.push_back({sum / (3 * n), std::sqrt(variance) / n, 0});
  }
  return out;
}

double difference_score(const RegionEstimate& a, const RegionEstimate& b) {
  const double rounding = 1e-5 * (std::abs(a.mean) + std::abs(b.mean));
  const double se2 = a.standard_error * a.standard_error + b.standard_error * b.standard_error + rounding * rounding;
  return se2 > 0 ? (a.mean - b.mean) / std::sqrt(se2) : 0;
}

testing::AssertionResult agrees_with_exact(const Region& region, const RegionEstimate& estimate, double exact,
                                           double t_critical) {
  if (std::abs(difference_score(estimate, {exact, 0, 1})) < t_critical) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "region (" << region.lo.x << ", " << region.lo.y << "): " << estimate.mean
                                     << " +- " << estimate.standard_error << ", exactly " << exact;
}

std::pair<double, double> mean_and_standard_error(const std::vector<double>& values) {
  double sum = 0, sum2 = 0;
  for (double x : values) sum += x;
  const double mean = sum / double(values.size());
  for (double x : values) sum2 += (x - mean) * (x - mean);
  return {mean, std::sqrt(sum2 / double(values.size() - 1) / double(values.size()))};
}

}  // namespace caustica::test

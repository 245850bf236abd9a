// A second oracle for the spot light, beside its sampled flux
// (emitter_test.cpp): a diffuse floor lit by a spot alone, pointing straight
// down from height h, seen from straight above.
// A floor point at distance r from the axis receives
//   E(r) = I(theta) cos(theta) / (r^2 + h^2),  tan(theta) = r / h,
// with I(theta) the intensity, constant within beam_width of the axis and
// falling linearly in angle to nothing at cutoff_angle, and shows
// reflectance / pi x E(r) (next-event estimation toward a delta light draws
// nothing that changes the value). E falls with r, and a pixel's value is
// the mean of such values at points within its footprint (a box filter), so
// it must lie between E at the footprint's farthest and nearest points from
// the axis, whatever the samples. Light tracing, which draws the spot's
// emitted flux instead, must match the footprints' mean of it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/math/constants.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kIntensity = 3, kHeight = 1, kReflectance = 0.5, kBeam = 10, kCutoff = 50;
constexpr double kEye = 5, kFov = 33.4;  // degrees across x
constexpr int kPixels = 48;
// The camera, looking straight down, sees [-w, w] of the floor along x and
// y: a pixel's footprint there is a square.
const double kHalfWidth = kEye * std::tan(kFov * kPi / 360);

double radiance_at(double r) {
  const double theta = std::atan2(r, kHeight), b = kBeam * kPi / 180, c = kCutoff * kPi / 180;
  const double intensity = theta <= b ? kIntensity : theta >= c ? 0 : kIntensity * (c - theta) / (c - b);
  const double d2 = r * r + kHeight * kHeight;
  return kReflectance / kPi * intensity * (kHeight / std::sqrt(d2)) / d2;
}

// The distance from the axis to the nearest and farthest points of the
// interval [lo, hi] along one axis.
double nearest(double lo, double hi) { return lo <= 0 && hi >= 0 ? 0 : std::min(std::abs(lo), std::abs(hi)); }
double farthest(double lo, double hi) { return std::max(std::abs(lo), std::abs(hi)); }

// Pixel (i, j)'s footprint on the floor, up to the image's flips, which the
// light's symmetry about its axis makes irrelevant: [x0, x0 + step] x [y0, y0 + step].
struct Footprint {
  double x0, y0, step;
};
Footprint footprint(int i, int j) {
  const double step = 2 * kHalfWidth / kPixels;
  return {-kHalfWidth + i * step, -kHalfWidth + j * step, step};
}

std::string scene_xml(const std::string& integrator) {
  const auto n = [](double x) { return std::to_string(x); };
  return "<scene version='3.0.0'><integrator type='" + integrator +
         "'/><sensor type='perspective'><float name='fov' value='" + n(kFov) +
         "'/><transform name='to_world'><lookat origin='0, 0, " + n(kEye) +
         "' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' value='" +
         std::to_string(kPixels) + "'/><integer name='height' value='" + std::to_string(kPixels) +
         "'/><rfilter type='box'/></film></sensor><shape type='rectangle'><transform name='to_world'><scale "
         "value='4'/></transform><bsdf type='diffuse'><rgb name='reflectance' value='" +
         n(kReflectance) + "'/></bsdf></shape><emitter type='spot'><rgb name='intensity' value='" + n(kIntensity) +
         "'/><float name='beam_width' value='" + n(kBeam) + "'/><float name='cutoff_angle' value='" + n(kCutoff) +
         "'/><transform name='to_world'><lookat origin='0, 0, " + n(kHeight) +
         "' target='0, 0, 0' up='0, 1, 0'/></transform></emitter></scene>";
}

// Next-event estimation: every pixel between the closed form at its
// footprint's farthest and nearest points.
TEST(SpotImage, EveryPixelWithinTheClosedFormOverItsFootprint) {
  const std::vector<float> px = test::render_scene(test::scene_from_xml(scene_xml("direct")), 16, 3, 2).resolve();
  ASSERT_EQ(px.size(), size_t(kPixels * kPixels * 3));
  int in_beam = 0, in_falloff = 0, dark = 0;
  for (int j = 0; j < kPixels; ++j)
    for (int i = 0; i < kPixels; ++i) {
      const Footprint f = footprint(i, j);
      const double r_near = std::hypot(nearest(f.x0, f.x0 + f.step), nearest(f.y0, f.y0 + f.step));
      const double r_far = std::hypot(farthest(f.x0, f.x0 + f.step), farthest(f.y0, f.y0 + f.step));
      const float value = px[size_t(j * kPixels + i) * 3];
      EXPECT_GE(value, radiance_at(r_far) * (1 - 1e-5) - 1e-7) << "pixel (" << i << ", " << j << ")";
      EXPECT_LE(value, radiance_at(r_near) * (1 + 1e-5) + 1e-7) << "pixel (" << i << ", " << j << ")";
      const double near_angle = std::atan2(r_near, kHeight) * 180 / kPi;
      const double far_angle = std::atan2(r_far, kHeight) * 180 / kPi;
      in_beam += far_angle < kBeam;
      in_falloff += near_angle > kBeam && far_angle < kCutoff;
      dark += near_angle > kCutoff;
    }
  // The image holds the beam, the fall-off and the dark beyond it.
  EXPECT_GT(in_beam, 4);
  EXPECT_GT(in_falloff, 500);
  EXPECT_GT(dark, 100);
}

// Light tracing draws the spot's emission (its flux over the cone), not its
// intensity toward a point: each 6x6-pixel region's mean over independent
// runs agrees with the closed form averaged over the region's footprint
// (a 32x32 midpoint grid per pixel), two-sided at 1 %, Sidak-corrected over
// the regions.
TEST(SpotImage, LightTracingAgreesWithTheClosedFormRegionByRegion) {
  const auto regions = test::grid_regions(kPixels, kPixels, 8);
  const auto estimates = test::estimate_regions(test::scene_from_xml(scene_xml("ptracer")), regions, 16, 16, 40);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(regions.size())), 15);
  constexpr int kSub = 32;
  for (size_t k = 0; k < regions.size(); ++k) {
    double sum = 0;
    for (int j = regions[k].lo.y; j < regions[k].hi.y; ++j)
      for (int i = regions[k].lo.x; i < regions[k].hi.x; ++i) {
        const Footprint f = footprint(i, j);
        for (int b = 0; b < kSub; ++b)
          for (int a = 0; a < kSub; ++a)
            sum += radiance_at(std::hypot(f.x0 + (a + 0.5) * f.step / kSub, f.y0 + (b + 0.5) * f.step / kSub));
      }
    const int pixels = (regions[k].hi.x - regions[k].lo.x) * (regions[k].hi.y - regions[k].lo.y);
    EXPECT_TRUE(test::agrees_with_exact(regions[k], estimates[k], sum / (double(pixels) * kSub * kSub), t_critical));
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

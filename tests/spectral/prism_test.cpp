// A prism splitting a white beam: an equilateral N-SF11 prism
// (scenes/meshes/prism.obj) lit by a narrow spot light at the angle of
// minimum deviation for 550 nm, its spectrum falling on a white wall 8
// units away, which an orthographic camera sees from above; rendered
// spectrally by light tracing, photon mapping and sppm. Every column of
// the image is reduced to its dominant wavelength (the hue angle of its
// chromaticity about D65's white point, matched against the CIE 1931
// spectral locus). The wavelengths must fall along the spectrum, and each
// column's deviation angle, where it sits, must match the one Snell's law
// gives with the Sellmeier index (traced here in the prism's plane) for the
// wavelength it shows: over the columns showing 470-610 nm, the residuals'
// mean within 0.005 degrees and their root mean square within 0.03 (a
// pixel spans 0.036 degrees, the beam 0.006). Seen: light tracing 0.0003
// and 0.0012; photon mapping and sppm, whose passes each light one line
// (their photons meet the prism at the pass's hero wavelength), 0.0002
// and 0.015. 540-560 nm are left out: the spectral locus's hue changes
// least per nm there, so that noise moves the estimate most. The photon
// passes' image holds as much light as light tracing's, within 5% (their
// 128 passes' wavelengths sample the spectrum; seen 2.0% and 0.3%).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "core/color/cie_tables.h"
#include "core/scene/scene.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;

double sf11_index(double nm) {
  const double l2 = nm * nm * 1e-6;
  return std::sqrt(1 + 1.73759695 * l2 / (l2 - 0.013188707) + 0.313747346 * l2 / (l2 - 0.0623068142) +
                   1.89878101 * l2 / (l2 - 155.23629));
}

// Vectors in the prism's cross-section (the x-y plane).
struct V2 {
  double x, y;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
V2 operator*(V2 a, double s) { return {a.x * s, a.y * s}; }
double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
V2 unit(V2 a) { return a * (1 / std::sqrt(dot(a, a))); }

// Snell's law: d refracted through a face whose normal n points against d,
// from index n1 into n2.
std::optional<V2> refract(V2 d, V2 n, double n1, double n2) {
  const double eta = n1 / n2, c = -dot(d, n), k = 1 - eta * eta * (1 - c * c);
  if (k < 0) return std::nullopt;
  return d * eta + n * (eta * c - std::sqrt(k));
}

// Where the ray p + t d meets the line through a and b.
V2 meet(V2 p, V2 d, V2 a, V2 b) {
  const V2 e = b - a;
  const double t = ((a.x - p.x) * e.y - (a.y - p.y) * e.x) / (d.x * e.y - d.y * e.x);
  return p + d * t;
}

const double kRoot3 = std::sqrt(3.0);
const V2 kApex{0, kRoot3}, kLeftBase{-1, 0}, kRightBase{1, 0};
const V2 kLeftNormal{-kRoot3 / 2, 0.5}, kRightNormal{kRoot3 / 2, 0.5};  // outward
const V2 kEntry = (kApex + kLeftBase) * 0.5;
const double kWallDistance = 8;

// The beam: inside the prism it runs parallel to the base at 550 nm, so it
// arrives along the reverse of that ray refracted out of the left face.
V2 beam_direction() { return *refract(V2{-1, 0}, kLeftNormal * -1.0, sf11_index(550), 1) * -1.0; }

struct Exit {
  V2 point, direction;
};
Exit through_prism(double nm) {
  const V2 inside = *refract(beam_direction(), kLeftNormal, 1, sf11_index(nm));
  const V2 exit = meet(kEntry, inside, kApex, kRightBase);
  return {exit, unit(*refract(inside, kRightNormal * -1.0, sf11_index(nm), 1))};
}

struct Wall {
  V2 centre, normal, across;  // normal toward the wall, `across` along it in the prism's plane
};
Wall wall() {
  const Exit e = through_prism(550);
  const V2 across{-e.direction.y, e.direction.x};
  return {e.point + e.direction * kWallDistance + across * -0.1, e.direction, across};
}

// Where a wavelength lands on the wall, along `across` from its centre.
double landing(double nm) {
  const Exit e = through_prism(nm);
  const Wall w = wall();
  const double t = dot(w.centre - e.point, w.normal) / dot(e.direction, w.normal);
  return dot(e.point + e.direction * t - w.centre, w.across);
}

// The deviation (degrees) of the ray from wavelength nm's exit point to the
// point `along` on the wall.
double deviation_to(double nm, double along) {
  const Wall w = wall();
  const V2 to = unit(w.centre + w.across * along - through_prism(nm).point);
  return std::acos(dot(to, beam_direction())) * 180 / kPi;
}

constexpr int kWidth = 240, kHeight = 48;
constexpr double kHalfWidth = 0.6;  // of the wall the film sees, along `across`

std::string prism_scene(const std::string& integrator) {
  const V2 beam = beam_direction(), source = kEntry - beam * 3;
  const Wall w = wall();
  // The camera looks at the wall from above, 35 degrees out of the
  // prism's plane, so the prism does not hide it.
  const double tilt = 35 * kPi / 180;
  const double fx = w.normal.x * std::cos(tilt), fy = w.normal.y * std::cos(tilt), fz = -std::sin(tilt);
  std::ostringstream xml;
  xml.precision(10);
  xml << "<scene version='3.0.0'>" << integrator
      << "<emitter type='spot'><rgb name='intensity' value='1000'/><float name='cutoff_angle' value='0.05'/>"
      << "<float name='beam_width' value='0.05'/><transform name='to_world'><lookat origin='" << source.x << ", "
      << source.y << ", 0' target='" << kEntry.x << ", " << kEntry.y << ", 0' up='0, 0, 1'/></transform></emitter>"
      << "<shape type='obj'><string name='filename' value='" << CAUSTICA_SOURCE_DIR << "/scenes/meshes/prism.obj'/>"
      << "<boolean name='face_normals' value='true'/>"
      << "<bsdf type='dielectric'><string name='dispersion' value='sf11'/><string name='ext_ior' value='vacuum'/>"
      << "</bsdf></shape>"
      << "<shape type='rectangle'><bsdf type='diffuse'/><transform name='to_world'><scale x='2' y='2'/>"
      << "<lookat origin='" << w.centre.x << ", " << w.centre.y << ", 0' target='" << w.centre.x - w.normal.x << ", "
      << w.centre.y - w.normal.y << ", 0' up='0, 0, 1'/></transform></shape>"
      << "<sensor type='orthographic'><transform name='to_world'><scale x='" << kHalfWidth << "' y='" << kHalfWidth
      << "'/><lookat origin='" << w.centre.x - 10 * fx << ", " << w.centre.y - 10 * fy << ", " << -10 * fz
      << "' target='" << w.centre.x << ", " << w.centre.y << ", 0' up='0, 0, 1'/></transform>"
      << "<sampler type='independent'/><film type='hdrfilm'><integer name='width' value='" << kWidth
      << "'/><integer name='height' value='" << kHeight << "'/><rfilter type='box'/></film></sensor></scene>";
  return xml.str();
}

// Where column c's centre sees the wall, along `across`. The film's x runs
// opposite to the camera's left, cross(up, forward), which is `across` here.
double column_position(double c) { return kHalfWidth * (1 - 2 * (c + 0.5) / kWidth); }

double table_at(const std::array<double, kCieSamples>& t, double nm) {
  const double x = (nm - kCieFirstNm) / kCieStepNm;
  const size_t i = size_t(x);
  return t[i] + (t[i + 1] - t[i]) * (x - double(i));
}

// The hue angle of a chromaticity about D65's white point (0.3127, 0.3290).
double hue(double x, double y) { return std::atan2(y - 0.3290, x - 0.3127); }

// The wavelength in [440, 640] nm whose spectral colour has the hue of XYZ
// (the hue falls monotonically with wavelength there, but for its one jump
// from -pi to pi near 492 nm).
std::optional<double> dominant_wavelength(const std::array<double, 3>& xyz) {
  const double sum = xyz[0] + xyz[1] + xyz[2];
  const double h = hue(xyz[0] / sum, xyz[1] / sum);
  const auto locus_hue = [](double nm) {
    const double X = table_at(kCieX, nm), Y = table_at(kCieY, nm), Z = table_at(kCieZ, nm);
    return hue(X / (X + Y + Z), Y / (X + Y + Z));
  };
  for (double nm = 440; nm < 640; nm += 0.1) {
    const double h0 = locus_hue(nm), h1 = locus_hue(nm + 0.1);
    if (std::abs(h1 - h0) < kPi && (h - h0) * (h - h1) <= 0) return nm + 0.1 * (h - h0) / (h1 - h0);
  }
  return std::nullopt;
}

// Each column's XYZ, from linear Rec.709 (IEC 61966-2-1).
std::vector<std::array<double, 3>> column_xyz(const LoadedScene& scene, uint32_t spp) {
  const auto rgb = test::render_scene(scene, spp, 3).resolve();
  std::vector<std::array<double, 3>> columns(kWidth, {0, 0, 0});
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = 3 * size_t(y * kWidth + x);
      const double r = rgb[i], g = rgb[i + 1], b = rgb[i + 2];
      auto& c = columns[size_t(x)];
      c[0] += 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
      c[1] += 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
      c[2] += 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
    }
  return columns;
}

double total_luminance(const std::vector<std::array<double, 3>>& columns) {
  double total = 0;
  for (const auto& c : columns) total += c[1];
  return total;
}

struct PrismRender {
  const char* name;
  const char* integrator;
  uint32_t spp;
};

// Photon mapping's passes each light the wall at one wavelength (their
// photons meet the prism at the pass's hero wavelength): 128 passes spread
// them over the spectrum, their gather radius below a pixel's width.
const PrismRender kPrismRenders[] = {
    {"ptracer", "<integrator type='ptracer'/>", 64},
    {"photon",
     "<integrator type='photon'><integer name='photons' value='20000'/><float name='radius' value='0.004'/>"
     "</integrator>",
     128},
    {"sppm",
     "<integrator type='sppm'><integer name='photons' value='20000'/><float name='radius' value='0.004'/>"
     "</integrator>",
     128}};

class Prism : public testing::TestWithParam<PrismRender> {};

TEST_P(Prism, SpreadsWavelengthsBySnellsLaw) {
  const auto scene = test::scene_from_xml(prism_scene(GetParam().integrator));
  ASSERT_TRUE(scene->features().spectral);
  const std::vector<std::array<double, 3>> columns = column_xyz(scene, GetParam().spp);
  double brightest = 0;
  for (const auto& c : columns) brightest = std::max(brightest, c[1]);
  ASSERT_GT(brightest, 0);
  // Columns bright enough to read, with their dominant wavelengths.
  std::vector<std::pair<double, double>> seen;  // (column, nm)
  for (int x = 0; x < kWidth; ++x)
    if (columns[size_t(x)][1] > 0.02 * brightest)
      if (const auto nm = dominant_wavelength(columns[size_t(x)])) seen.emplace_back(x, *nm);
  ASSERT_GT(seen.size(), 40u);
  // Blue is bent most, landing further along -across, which is the film's
  // x: wavelengths fall along it.
  ASSERT_LT(landing(450), landing(650));
  for (size_t k = 8; k < seen.size(); ++k) EXPECT_LT(seen[k].second, seen[k - 8].second) << "column " << seen[k].first;
  // Each column's deviation, where it sits, against Snell's for the
  // wavelength it shows.
  double sum = 0, sum2 = 0;
  int n = 0;
  for (const auto& [column, nm] : seen) {
    if (nm < 470 || nm > 610 || (nm > 540 && nm < 560)) continue;
    const double residual = deviation_to(nm, column_position(column)) - deviation_to(nm, landing(nm));
    sum += residual;
    sum2 += residual * residual;
    ++n;
  }
  ASSERT_GT(n, 30);
  const double mean = sum / n, rms = std::sqrt(sum2 / n);
  EXPECT_LT(std::abs(mean), 0.005) << n << " columns";
  EXPECT_LT(rms, 0.03) << n << " columns";
  // The light the photon passes carry in all, against light tracing's.
  if (std::string(GetParam().name) != "ptracer") {
    const auto traced = test::scene_from_xml(prism_scene("<integrator type='ptracer'/>"));
    EXPECT_NEAR(total_luminance(columns) / total_luminance(column_xyz(traced, 64)), 1, 0.05);
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, Prism, testing::ValuesIn(kPrismRenders),
                         [](const testing::TestParamInfo<PrismRender>& info) { return std::string(info.param.name); });

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

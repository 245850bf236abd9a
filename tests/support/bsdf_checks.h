#pragma once

// Checks every BSDF plugin must pass, shared by the material tests:
// chi-square of sample() against pdf(), sample/eval/pdf agreement, pdf
// normalisation, reciprocity and energy (white furnace).

#include <cmath>
#include <memory>
#include <string>

#include "core/bsdf/bsdf.h"
#include "tests/support/chi2.h"

namespace caustica::test {

// The chi-square tests of all material files together (bumpmap 6,
// blendbsdf 6, dielectric 6, diffuse 8, mask 6, microfacet 30, phong 12, plastic 12,
// principled 19, principledthin 16, roughconductor 44, roughdielectric 78, roughplastic 26, thindielectric 8,
// twosided 4):
// each test runs at the Sidak-corrected level that keeps the chance of any
// false failure in the whole set at 1%. A file adding tests adds them here.
inline constexpr int kMaterialChi2Tests = 281;
inline double material_chi2_alpha() { return sidak_alpha(0.01, kMaterialChi2Tests); }

inline const BsdfContext kRadiance{TransportMode::Radiance, {}};
inline const BsdfContext kImportance{TransportMode::Importance, {}};

// w mirrored through the surface, to the other side.
inline Vec3 below(Vec3 w) { return {w.x, w.y, -w.z}; }

// A sample's throughput weight f |cos| / pdf (green channel).
inline float sample_weight(const BsdfSample& s) { return s.f.g * std::abs(s.wi.z) / s.pdf; }

// int_ior and ext_ior elements giving the relative index eta, the smaller
// of the two indices being 1.
std::string ior_params(float eta);

// A BSDF from its XML element, e.g. "<bsdf type='diffuse'/>", through the
// scene loader (so parameters are parsed exactly as in a scene file).
std::shared_ptr<Bsdf> make_bsdf(const std::string& element);

// A unit direction at polar angle theta (radians) from +z and azimuth phi.
Vec3 direction(float theta, float phi = 0.3f);

// Chi-square of sample() against pdf() for the given wo. Samples of delta
// lobes count as failures, expected as often as the pdf leaves mass out.
Chi2Result chi2_bsdf(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, const Chi2Options& options = {});

struct SampleConsistency {
  int checked = 0;                            // non-delta samples compared
  double max_f_error = 0, max_pdf_error = 0;  // relative
  int non_finite = 0;                         // samples with NaN/Inf f, pdf or direction
};
// For n samples: f and pdf of each non-delta sample against eval() and
// pdf() in the same direction, and everything finite.
SampleConsistency check_samples(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, int n, uint32_t seed = 1);

// Integral of pdf(wo, .) over the sphere (at most 1; less where delta lobes
// or absorbed samples take the rest).
double pdf_integral(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx);

struct AlbedoEstimate {
  Color mean, standard_error;
};
// Directional albedo from wo: the mean of f |cos| / pdf over n samples
// (delta lobes included), the white-furnace quantity.
AlbedoEstimate albedo(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, int n, uint32_t seed = 2);

// Largest relative difference between eval(a, b) and eval(b, a) over n
// random pairs of directions (both hemispheres when `transmission`).
double reciprocity_error(const Bsdf& bsdf, const BsdfContext& ctx, int n, bool transmission = false, uint32_t seed = 3);

}  // namespace caustica::test

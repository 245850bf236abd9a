#include "tests/support/bsdf_checks.h"

#include <cmath>

#include "core/sampling/warp.h"
#include "tests/support/test_scenes.h"

namespace caustica::test {

std::shared_ptr<Bsdf> make_bsdf(const std::string& element) {
  const auto scene =
      scene_from_xml("<scene version='3.0.0'><shape type='rectangle'>" + element + "</shape></scene>", "bsdf.xml");
  return scene->shapes().front()->bsdf();
}

std::string ior_params(float eta) {
  const float int_ior = std::max(eta, 1.0f), ext_ior = int_ior / eta;
  return "<float name='int_ior' value='" + std::to_string(int_ior) + "'/><float name='ext_ior' value='" +
         std::to_string(ext_ior) + "'/>";
}

Vec3 direction(float theta, float phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Chi2Result chi2_bsdf(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, const Chi2Options& options) {
  return chi2_test_sphere(
      [&](UniformSource& u) -> std::optional<Vec3> {
        const float u_lobe = u.next_1d();
        const auto s = bsdf.sample(ctx, wo, u_lobe, u.next_2d());
        if (!s || s->is_delta() || !(s->pdf > 0)) return std::nullopt;
        return s->wi;
      },
      [&](const Vec3& wi) { return double(bsdf.pdf(ctx, wo, wi)); }, options);
}

SampleConsistency check_samples(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, int n, uint32_t seed) {
  UniformSource u(seed);
  SampleConsistency out;
  const auto relative = [](double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-6}); };
  for (int i = 0; i < n; ++i) {
    const float u_lobe = u.next_1d();
    const auto s = bsdf.sample(ctx, wo, u_lobe, u.next_2d());
    if (!s) continue;
    if (!s->f.is_finite() || !std::isfinite(s->pdf) || !is_finite(s->wi)) {
      ++out.non_finite;
      continue;
    }
    if (s->is_delta()) continue;
    ++out.checked;
    const Color f = bsdf.eval(ctx, wo, s->wi);
    for (int c = 0; c < 3; ++c) out.max_f_error = std::max(out.max_f_error, relative(s->f[c], f[c]));
    out.max_pdf_error = std::max(out.max_pdf_error, relative(s->pdf, bsdf.pdf(ctx, wo, s->wi)));
  }
  return out;
}

double pdf_integral(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx) {
  return integrate_sphere([&](const Vec3& wi) { return double(bsdf.pdf(ctx, wo, wi)); });
}

AlbedoEstimate albedo(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, int n, uint32_t seed) {
  UniformSource u(seed);
  double sum[3] = {}, sum2[3] = {};
  for (int i = 0; i < n; ++i) {
    const float u_lobe = u.next_1d();
    const auto s = bsdf.sample(ctx, wo, u_lobe, u.next_2d());
    if (!s || !(s->pdf > 0)) continue;
    const Color w = s->f * (std::abs(s->wi.z) / s->pdf);
    for (int c = 0; c < 3; ++c) {
      sum[c] += w[c];
      sum2[c] += double(w[c]) * w[c];
    }
  }
  AlbedoEstimate out;
  float mean[3], se[3];
  for (int c = 0; c < 3; ++c) {
    mean[c] = float(sum[c] / n);
    se[c] = float(std::sqrt(std::max(0.0, sum2[c] / n - mean[c] * double(mean[c])) / (n - 1)));
  }
  out.mean = {mean[0], mean[1], mean[2]};
  out.standard_error = {se[0], se[1], se[2]};
  return out;
}

double reciprocity_error(const Bsdf& bsdf, const BsdfContext& ctx, int n, bool transmission, uint32_t seed) {
  UniformSource u(seed);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 a = square_to_uniform_hemisphere(u.next_2d());
    Vec3 b = square_to_uniform_hemisphere(u.next_2d());
    if (transmission && i % 2) b.z = -b.z;
    const Color ab = bsdf.eval(ctx, a, b), ba = bsdf.eval(ctx, b, a);
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(ab[c]) - ba[c]) / std::max({double(ab[c]), double(ba[c]), 1e-6}));
  }
  return worst;
}

}  // namespace caustica::test

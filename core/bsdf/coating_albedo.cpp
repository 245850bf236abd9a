#include "core/bsdf/coating_albedo.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/bsdf/fresnel.h"

namespace caustica {

CoatingAlbedo::CoatingAlbedo(MicrofacetDistribution::Type type, float alpha_lo, float alpha_hi, float eta)
    : alpha_lo_(alpha_lo), alpha_hi_(alpha_hi) {
  root_lo_ = std::sqrt(alpha_lo);
  // A range too narrow to resolve in sqrt(alpha) is one roughness.
  const float root_span = std::sqrt(alpha_hi) - root_lo_;
  const int n = root_span > 1e-4f * std::sqrt(alpha_hi) ? kAlphaNodes : 1;
  root_step_ = n > 1 ? root_span / float(n - 1) : 0;
  tables_.resize(size_t(n));
  // Each node's integral is independent and deterministic: computed in
  // parallel, the tables are the same on any number of threads.
  tbb::parallel_for(0, n * kMuNodes, [&](int job) {
    const int k = job / kMuNodes;
    const float root = root_lo_ + root_step_ * float(k);
    const float alpha = k == 0 ? alpha_lo : k + 1 == n ? alpha_hi : root * root;
    tables_[size_t(k)].e[size_t(job % kMuNodes)] =
        integrate(MicrofacetDistribution(type, alpha, alpha), eta, job % kMuNodes);
  });
  for (Table& table : tables_) {
    double mean = 0;
    for (int i = 0; i + 1 < kMuNodes; ++i) {
      const double a = mu_node(i), b = mu_node(i + 1);
      mean += (b - a) / 6 * (table.e[i] * (2 * a + b) + table.e[i + 1] * (a + 2 * b));
    }
    table.mean = float(std::min(2 * mean, 1 - 1e-6));
  }
}

// E(mu) at node i by stratified sampling of microfacet normals: with
// dwi = 4 (wo.m) dm the integrand over m is F D G (wo.m) / mu, divided by
// the density of sample(). The mean 2 int E mu dmu is exact for the
// piecewise linear E.
float CoatingAlbedo::integrate(const MicrofacetDistribution& dist, float eta, int i) {
  const float mu = std::max(mu_node(i), 1e-4f);
  const Vec3 wo(std::sqrt(std::max(0.0f, 1 - mu * mu)), 0, mu);
  double sum = 0;
  for (int a = 0; a < kStrata; ++a)
    for (int b = 0; b < kStrata; ++b) {
      const Vec3 m = dist.sample(wo, {(a + 0.5f) / kStrata, (b + 0.5f) / kStrata});
      const float wo_m = dot(wo, m), density = dist.pdf(wo, m);
      if (!(wo_m > 0) || !(density > 0)) continue;
      const Vec3 wi = reflect(wo, m);
      if (!(wi.z > 0)) continue;
      const double value =
          double(fresnel_dielectric(wo_m, eta).F) * dist.D(m) * dist.G(wo, wi, m) * wo_m / (mu * density);
      if (std::isfinite(value)) sum += value;
    }
  return float(std::clamp(sum / (kStrata * kStrata), 0.0, 1.0));
}

float CoatingAlbedo::mu_node(int i) {
  const float x = float(i) / (kMuNodes - 1);
  return x * x;
}

void CoatingAlbedo::bracket(float alpha, int* i, float* t) const {
  if (tables_.size() == 1 || alpha <= alpha_lo_ || alpha >= alpha_hi_) {
    *i = alpha >= alpha_hi_ ? int(tables_.size()) - 1 : 0;
    *t = 0;
    return;
  }
  const float x = std::clamp((std::sqrt(alpha) - root_lo_) / root_step_, 0.0f, float(tables_.size() - 1));
  *i = std::min(int(x), int(tables_.size()) - 2);
  *t = x - float(*i);
}

float CoatingAlbedo::operator()(float alpha, float mu) const {
  const float x = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * (kMuNodes - 1);
  const int j = std::min(int(x), kMuNodes - 2);
  const float s = std::clamp((mu - mu_node(j)) / (mu_node(j + 1) - mu_node(j)), 0.0f, 1.0f);
  const auto at = [&](const Table& table) { return table.e[j] * (1 - s) + table.e[j + 1] * s; };
  int i;
  float t;
  bracket(alpha, &i, &t);
  return t == 0 ? at(tables_[i]) : at(tables_[i]) * (1 - t) + at(tables_[i + 1]) * t;
}

float CoatingAlbedo::mean(float alpha) const {
  int i;
  float t;
  bracket(alpha, &i, &t);
  return t == 0 ? tables_[i].mean : tables_[i].mean * (1 - t) + tables_[i + 1].mean * t;
}

}  // namespace caustica

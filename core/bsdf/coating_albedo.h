#pragma once

#include <array>
#include <vector>

#include "core/bsdf/microfacet.h"

namespace caustica {

// The directional albedo E(mu) of a rough dielectric interface's reflection
// (the microfacet reflection with Fresnel, Smith's height-correlated G and
// no other scaling) at mu = cos(theta), and its cosine-weighted mean
// 2 int E mu dmu, for isotropic roughness alpha in [alpha_lo, alpha_hi]:
// tabulated over mu at a few roughness values across the range (one when
// the range is a single value; evenly spaced in sqrt(alpha), since E bends
// most at small roughness) and interpolated linearly in mu and sqrt(alpha).
class CoatingAlbedo {
 public:
  CoatingAlbedo(MicrofacetDistribution::Type type, float alpha_lo, float alpha_hi, float eta);

  float operator()(float alpha, float mu) const;
  float mean(float alpha) const;

 private:
  // Nodes at mu = (i / (kMuNodes - 1))^2, dense near grazing where E changes fastest.
  static constexpr int kMuNodes = 64;
  static constexpr int kStrata = 64;      // per axis, for each node's integral
  static constexpr int kAlphaNodes = 12;  // E within 2e-3 of a table of its own across [0.05, 0.6]
  struct Table {
    std::array<float, kMuNodes> e{};
    float mean = 0;
  };
  static float integrate(const MicrofacetDistribution& dist, float eta, int mu_node_index);
  static float mu_node(int i);
  // The two tables around alpha and the weight of the second.
  void bracket(float alpha, int* i, float* t) const;

  float alpha_lo_, alpha_hi_, root_lo_ = 0, root_step_ = 0;
  std::vector<Table> tables_;
};

}  // namespace caustica

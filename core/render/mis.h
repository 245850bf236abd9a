#pragma once

namespace caustica {

// Veach's power heuristic (beta = 2) for two strategies taking n_a and n_b
// samples with densities pdf_a and pdf_b; returns the weight of strategy a.
inline float power_heuristic(float n_a, float pdf_a, float n_b, float pdf_b) {
  const float a = n_a * pdf_a, b = n_b * pdf_b;
  if (a == 0) return 0;
  // Written as 1 / (1 + (b/a)^2) so a huge density does not overflow to inf/inf.
  const float r = b / a;
  return 1 / (1 + r * r);
}

}  // namespace caustica

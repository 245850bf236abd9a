#pragma once

#include <string>
#include <utility>
#include <vector>

namespace caustica {

// A dielectric's index of refraction as a function of wavelength, by one of
// the usual models (wavelengths in micrometres inside them):
//   constant   n
//   Cauchy     n = A + B / l^2 + C / l^4 + ...        (coefficients A, B, C, ...)
//   Sellmeier  n^2 = 1 + sum_i B_i l^2 / (l^2 - C_i)   (terms (B_i, C_i), C_i in um^2)
// or a named material with published Sellmeier coefficients: "bk7"
// (Schott N-BK7), "fused silica" (Malitson 1965), "diamond" (Peter 1923),
// "water" (Daimon and Masumura 2007, 20 degrees C), "sf11" (Schott N-SF11,
// a dense flint whose strong dispersion makes a clear prism spectrum).
class Dispersion {
 public:
  static Dispersion constant(double n);
  // Throw std::invalid_argument when the model has no coefficients or one
  // is not finite.
  static Dispersion cauchy(std::vector<double> coefficients);
  static Dispersion sellmeier(std::vector<std::pair<double, double>> terms);
  // Throws std::invalid_argument naming the materials it knows.
  static Dispersion named(const std::string& name);
  // As a scene writes it: a name above, "cauchy: A, B, C, ..." or
  // "sellmeier: B1, C1, B2, C2, ..."; throws std::invalid_argument saying
  // what is wrong.
  static Dispersion parse(const std::string& text);

  // The index at a wavelength in nm.
  double ior(double nm) const;
  bool is_dispersive() const { return kind_ != Kind::Constant; }
  // The index at the helium d line (587.56 nm), where glasses are quoted.
  double ior_d() const { return ior(kHeliumDNm); }
  static constexpr double kHeliumDNm = 587.5618;
  // (n_d - 1) / (n_F - n_C) at the helium d (587.56 nm) and hydrogen F
  // (486.13 nm) and C (656.27 nm) lines; infinite without dispersion.
  double abbe_number() const;

 private:
  enum class Kind { Constant, Cauchy, Sellmeier };
  Kind kind_ = Kind::Constant;
  std::vector<double> a_;  // n; Cauchy's A, B, C, ...; Sellmeier's B_i
  std::vector<double> c_;  // Sellmeier's C_i
};

}  // namespace caustica

#include "core/spectral/dispersion.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

void check_finite(const std::vector<double>& values, const std::string& model) {
  if (values.empty()) throw std::invalid_argument(model + " needs at least one coefficient");
  for (double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument(model + " coefficient " + std::to_string(v) + " is not finite");
}

struct NamedGlass {
  const char* name;
  std::vector<std::pair<double, double>> terms;
};

// Published Sellmeier coefficients (B_i, C_i in um^2).
const std::vector<NamedGlass>& named_glasses() {
  static const std::vector<NamedGlass> glasses = {
      {"bk7", {{1.03961212, 0.00600069867}, {0.231792344, 0.0200179144}, {1.01046945, 103.560653}}},
      {"fused silica",
       {{0.6961663, 0.0684043 * 0.0684043}, {0.4079426, 0.1162414 * 0.1162414}, {0.8974794, 9.896161 * 9.896161}}},
      {"diamond", {{0.3306, 0.1750 * 0.1750}, {4.3356, 0.1060 * 0.1060}}},
      {"water",
       {{5.684027565e-1, 5.101829712e-3},
        {1.726177391e-1, 1.821153936e-2},
        {2.086189578e-2, 2.620722293e-2},
        {1.130748688e-1, 1.069792721e1}}},
      {"sf11", {{1.73759695, 0.013188707}, {0.313747346, 0.0623068142}, {1.89878101, 155.23629}}},
  };
  return glasses;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Dispersion Dispersion::constant(double n) {
  check_finite({n}, "a constant index");
  Dispersion d;
  d.a_ = {n};
  return d;
}

Dispersion Dispersion::cauchy(std::vector<double> coefficients) {
  check_finite(coefficients, "Cauchy's model");
  Dispersion d;
  d.kind_ = Kind::Cauchy;
  d.a_ = std::move(coefficients);
  return d;
}

Dispersion Dispersion::sellmeier(std::vector<std::pair<double, double>> terms) {
  Dispersion d;
  d.kind_ = Kind::Sellmeier;
  for (const auto& [b, c] : terms) {
    d.a_.push_back(b);
    d.c_.push_back(c);
  }
  check_finite(d.a_, "Sellmeier's model");
  check_finite(d.c_, "Sellmeier's model");
  return d;
}

Dispersion Dispersion::named(const std::string& name) {
  std::string known;
  for (const NamedGlass& g : named_glasses()) {
    if (name == g.name) return sellmeier(g.terms);
    known += (known.empty() ? "" : ", ") + std::string(g.name);
  }
  throw std::invalid_argument("no dispersive material is named '" + name + "' (known: " + known + ")");
}

Dispersion Dispersion::parse(const std::string& text) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos) return named(text);
  const std::string model = text.substr(0, colon);
  std::string list = text.substr(colon + 1);
  std::replace(list.begin(), list.end(), ',', ' ');
  std::vector<double> numbers;
  std::istringstream in(list);
  for (std::string item; in >> item;) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (*end != '\0') throw std::invalid_argument("cannot read '" + item + "' as a number");
    numbers.push_back(v);
  }
  if (model == "cauchy") return cauchy(std::move(numbers));
  if (model == "sellmeier") {
    if (numbers.empty() || numbers.size() % 2 != 0)
      throw std::invalid_argument("Sellmeier's model takes pairs B, C (" + std::to_string(numbers.size()) +
                                  " numbers given)");
    std::vector<std::pair<double, double>> terms;
    for (size_t i = 0; i < numbers.size(); i += 2) terms.emplace_back(numbers[i], numbers[i + 1]);
    return sellmeier(std::move(terms));
  }
  throw std::invalid_argument("unknown dispersion model '" + model + "' (known: cauchy, sellmeier)");
}

double Dispersion::ior(double nm) const {
  const double um = nm * 1e-3, um2 = um * um;
  switch (kind_) {
    case Kind::Constant:
      return a_[0];
    case Kind::Cauchy: {
      double n = 0, power = 1;
      for (double a : a_) {
        n += a / power;
        power *= um2;
      }
      return n;
    }
    case Kind::Sellmeier: {
      double n2 = 1;
      for (size_t i = 0; i < a_.size(); ++i) n2 += a_[i] * um2 / (um2 - c_[i]);
      return std::sqrt(n2);
    }
  }
  return a_[0];
}

double Dispersion::abbe_number() const {
  const double spread = ior(486.1327) - ior(656.2725);
  if (spread == 0) return std::numeric_limits<double>::infinity();
  return (ior(587.5618) - 1) / spread;
}

}  // namespace caustica

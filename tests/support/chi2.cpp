#include "tests/support/chi2.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/math/constants.h"

namespace caustica::test {

float UniformSource::next_1d() {
  // uniform_real_distribution<float> may round up to exactly 1.
  return std::min(dist_(rng_), kOneMinusEpsilon);
}

Vec2 UniformSource::next_2d() {
  const float x = next_1d();
  return {x, next_1d()};
}

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Adaptive Simpson quadrature, nested for the two dimensions of a bin. Each
// level of refinement costs two evaluations, so a jump inside a bin (the rim of
// a disk, the edge of a pdf's support) is chased down to a 2^-kMaxLevel
// fraction of the bin cheaply. That matters beyond the inner integral itself:
// its error is noise in the outer integrand, and if that noise exceeded the
// outer tolerance the outer integral would refine to the maximum level all
// over the bin.
// Capped so that a steep peak cannot make refinement exponential in cost.
constexpr int kMaxLevel = 16;
// Panels of the first, non-adaptive pass: enough nodes that a pdf which is
// small at the bin's centre and edges is not mistaken for zero.
constexpr int kFirstPanels = 4;
// Relative tolerances: the inner one well below the outer, for the reason
// above, and both above the float rounding noise of pdfs evaluated at float
// coordinates, which no refinement can remove.
constexpr double kInnerTolerance = 1e-6;
constexpr double kOuterTolerance = 1e-4;
// The bin's own edges are evaluated this fraction of a bin inside it: a pdf may
// be discontinuous exactly there (the horizon, a cone's rim on a bin edge) and
// should be seen from the bin's side, or undefined there (the poles, a pdf
// dividing by cos(theta) at the horizon). The shift is large enough to move a
// float coordinate, and its effect on the integral is of the same order.
constexpr double kEdgeInset = 1e-5;
// Absolute tolerance per unit of domain length.
constexpr double kAbsoluteFloor = 1e-9;

// A panel is accepted when its error estimate is within the tolerance relative
// to its own value, or within its share (by width) of the absolute tolerance of
// the whole integral; the latter stops refinement where a pdf is tiny.
template <typename F>
double simpson_refine(const F& f, double a, double b, double fa, double fm, double fb, double whole, double rel_tol,
                      double abs_tol, int level) {
  const double m = 0.5 * (a + b);
  const double flm = f(0.5 * (a + m));
  const double frm = f(0.5 * (m + b));
  const double left = (m - a) / 6 * (fa + 4 * flm + fm);
  const double right = (b - m) / 6 * (fm + 4 * frm + fb);
  const double refined = left + right;
  const double delta = refined - whole;
  // |delta| / 15 estimates the error of the refined value (Richardson), which
  // is also why adding it improves the result. A pdf returning NaN or infinity
  // ends the refinement at once, and the bin's expected count reports it.
  if (level >= kMaxLevel || !std::isfinite(delta) ||
      std::abs(delta) <= 15 * std::max(abs_tol, rel_tol * std::abs(refined)))
    return refined + delta / 15;
  return simpson_refine(f, a, m, fa, flm, fm, left, rel_tol, abs_tol / 2, level + 1) +
         simpson_refine(f, m, b, fm, frm, fb, right, rel_tol, abs_tol / 2, level + 1);
}

template <typename F>
double integrate_1d(const F& f, double a, double b, double rel_tol) {
  constexpr int kNodes = 2 * kFirstPanels + 1;
  const double step = (b - a) / (kNodes - 1);
  std::array<double, kNodes> fx;
  for (int i = 0; i < kNodes; ++i) {
    const double x = i == 0 ? a + kEdgeInset * (b - a) : i == kNodes - 1 ? b - kEdgeInset * (b - a) : a + i * step;
    fx[i] = f(x);
  }
  std::array<double, kFirstPanels> coarse;
  double total = 0;
  for (int p = 0; p < kFirstPanels; ++p) {
    coarse[p] = step / 3 * (fx[2 * p] + 4 * fx[2 * p + 1] + fx[2 * p + 2]);
    total += coarse[p];
  }
  // The floor stops refinement of a panel whose coarse estimate is zero (a
  // peak between the nodes, or nothing at all) once its error is negligible
  // next to any density a test compares against.
  const double abs_tol = std::max(rel_tol * std::abs(total) / kFirstPanels, kAbsoluteFloor * (b - a));
  double sum = 0;
  for (int p = 0; p < kFirstPanels; ++p) {
    const double x0 = a + 2 * p * step;
    sum +=
        simpson_refine(f, x0, x0 + 2 * step, fx[2 * p], fx[2 * p + 1], fx[2 * p + 2], coarse[p], rel_tol, abs_tol, 1);
  }
  return sum;
}

using Function2D = std::function<double(double, double)>;

// Integrals of f over a bins_u x bins_v grid on the rectangle, row-major in u.
std::vector<double> bin_integrals(const Function2D& f, const Rect& r, int bins_u, int bins_v) {
  std::vector<double> out(static_cast<size_t>(bins_u) * bins_v);
  const double du = (r.x1 - r.x0) / bins_u, dv = (r.y1 - r.y0) / bins_v;
  for (int i = 0; i < bins_u; ++i)
    for (int j = 0; j < bins_v; ++j) {
      const double v0 = r.y0 + j * dv, v1 = r.y0 + (j + 1) * dv;
      const auto inner = [&](double u) {
        return integrate_1d([&](double v) { return f(u, v); }, v0, v1, kInnerTolerance);
      };
      out[static_cast<size_t>(i) * bins_v + j] =
          integrate_1d(inner, r.x0 + i * du, r.x0 + (i + 1) * du, kOuterTolerance);
    }
  return out;
}

Vec3 direction_from(double cos_theta, double phi) {
  const double sin_theta = std::sqrt(std::max(0.0, (1 - cos_theta) * (1 + cos_theta)));
  return {static_cast<float>(sin_theta * std::cos(phi)), static_cast<float>(sin_theta * std::sin(phi)),
          static_cast<float>(cos_theta)};
}

Function2D sphere_integrand(const DirectionPdf& pdf) {
  return [&pdf](double cos_theta, double phi) { return pdf(direction_from(cos_theta, phi)); };
}

Function2D rect_integrand(const PointPdf& pdf) {
  return [&pdf](double x, double y) { return pdf(Vec2(static_cast<float>(x), static_cast<float>(y))); };
}

const Rect kSphereParameters{-1, 1, 0, kTwoPi};

int bin_index(double x, double lo, double hi, int bins) {
  return std::clamp(static_cast<int>((x - lo) / (hi - lo) * bins), 0, bins - 1);
}

std::string bin_label(const Rect& r, int bins_u, int bins_v, size_t bin, const char* u_name, const char* v_name) {
  const int i = static_cast<int>(bin / bins_v), j = static_cast<int>(bin % bins_v);
  const double du = (r.x1 - r.x0) / bins_u, dv = (r.y1 - r.y0) / bins_v;
  std::ostringstream s;
  s << std::setprecision(4) << u_name << " in [" << r.x0 + i * du << ", " << r.x0 + (i + 1) * du << "), " << v_name
    << " in [" << r.y0 + j * dv << ", " << r.y0 + (j + 1) * dv << ")";
  return s.str();
}

using LabelFunction = std::function<std::string(size_t)>;

struct Category {
  double observed = 0, expected = 0;
  std::string label;
  double contribution() const { return (observed - expected) * (observed - expected) / expected; }
};

Chi2Result evaluate(std::span<const double> observed, std::span<const double> expected, const LabelFunction& label,
                    double min_expected, const std::string& preface) {
  Chi2Result result;
  std::ostringstream report;
  report << preface << std::setprecision(6);

  // Checked first: NaN would otherwise slip through every comparison below and
  // the bin would silently drop out of the test.
  for (size_t i = 0; i < expected.size(); ++i)
    if (!std::isfinite(expected[i]) || expected[i] < 0) {
      result.statistic = std::numeric_limits<double>::quiet_NaN();
      report << label(i) << ": expected count " << expected[i] << "; the pdf must be finite and non-negative\n";
      result.report = report.str();
      return result;
    }

  std::vector<size_t> impossible;
  for (size_t i = 0; i < observed.size(); ++i)
    if (expected[i] <= 0 && observed[i] > 0) impossible.push_back(i);
  if (!impossible.empty()) {
    std::sort(impossible.begin(), impossible.end(), [&](size_t a, size_t b) { return observed[a] > observed[b]; });
    result.statistic = std::numeric_limits<double>::infinity();
    result.p_value = 0;
    report << impossible.size() << " bins received samples where the pdf integrates to zero:\n";
    for (size_t k = 0; k < std::min<size_t>(impossible.size(), 8); ++k)
      report << "  " << label(impossible[k]) << ": observed " << observed[impossible[k]] << "\n";
    result.report = report.str();
    return result;
  }

  std::vector<Category> categories;
  Category pooled{0, 0, "pooled bins"};
  int pooled_count = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] >= min_expected) {
      categories.push_back({observed[i], expected[i], label(i)});
    } else if (expected[i] > 0) {
      pooled.observed += observed[i];
      pooled.expected += expected[i];
      ++pooled_count;
    }
  }
  if (pooled_count > 0) {
    report << "pooled " << pooled_count << " bins expecting < " << min_expected << " samples: observed "
           << pooled.observed << ", expected " << pooled.expected << "\n";
    if (pooled.expected >= min_expected || categories.empty()) {
      categories.push_back(pooled);
    } else {
      // Still too small to stand alone: merge into the smallest category,
      // where it perturbs the statistic least.
      auto smallest = std::min_element(categories.begin(), categories.end(),
                                       [](const Category& a, const Category& b) { return a.expected < b.expected; });
      smallest->observed += pooled.observed;
      smallest->expected += pooled.expected;
      smallest->label += " (+ pooled bins)";
    }
  }
  if (categories.size() < 2) {
    result.p_value = 0;
    report << "too few populated bins for a chi-square test; raise the sample count\n";
    result.report = report.str();
    return result;
  }

  for (const Category& c : categories) result.statistic += c.contribution();
  result.dof = static_cast<int>(categories.size()) - 1;
  result.p_value = chi2_p_value(result.statistic, result.dof);
  report << "chi-square statistic " << result.statistic << " with " << result.dof << " degrees of freedom, p-value "
         << result.p_value << "\nlargest contributions:\n";
  const size_t shown = std::min<size_t>(categories.size(), 8);
  std::partial_sort(categories.begin(), categories.begin() + shown, categories.end(),
                    [](const Category& a, const Category& b) { return a.contribution() > b.contribution(); });
  for (size_t k = 0; k < shown; ++k) {
    const Category& c = categories[k];
    report << "  " << c.label << ": observed " << c.observed << ", expected " << c.expected << ", contribution "
           << c.contribution() << "\n";
  }
  result.report = report.str();
  return result;
}

// Shared tail of the sphere and rectangle tests: expected counts from the
// per-bin pdf integrals, plus the failure category (stored last in observed).
Chi2Result finish(const std::vector<double>& observed, const std::vector<double>& integrals,
                  const std::string& domain_name, const std::string& bad_example, const LabelFunction& grid_label,
                  const Chi2Options& options) {
  const double n = options.sample_count;
  std::vector<double> expected(observed.size());
  double total = 0;
  for (size_t i = 0; i < integrals.size(); ++i) {
    expected[i] = n * integrals[i];
    total += integrals[i];
  }
  expected.back() = n * std::max(0.0, 1 - total);

  std::ostringstream preface;
  preface << std::setprecision(8) << options.sample_count << " samples; the pdf integrates to " << total << " over the "
          << domain_name << "; " << observed.back() << " samples failed or were invalid";
  if (!bad_example.empty()) preface << " (for example " << bad_example << ")";
  preface << "\n";
  const size_t failure = integrals.size();
  const auto label = [&](size_t i) { return i == failure ? std::string("failed or invalid samples") : grid_label(i); };
  return evaluate(observed, expected, label, options.min_expected, preface.str());
}

std::string to_string(Vec3 v) {
  std::ostringstream s;
  s << std::setprecision(9) << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

std::string to_string(Vec2 v) {
  std::ostringstream s;
  s << std::setprecision(9) << "(" << v.x << ", " << v.y << ")";
  return s.str();
}

}  // namespace

Chi2Result chi2_test_sphere(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options) {
  const int bins_u = options.bins_u, bins_v = options.bins_v;
  const size_t grid = static_cast<size_t>(bins_u) * bins_v;
  std::vector<double> observed(grid + 1, 0.0);
  std::string bad_example;
  UniformSource source(options.seed);
  for (int n = 0; n < options.sample_count; ++n) {
    const std::optional<Vec3> w = sample(source);
    if (!w) {
      observed[grid] += 1;
      continue;
    }
    const double x = w->x, y = w->y, z = w->z;
    // Unit length to well within float accuracy; anything else is a bug in
    // the sampler, not a direction.
    if (!is_finite(*w) || std::abs(x * x + y * y + z * z - 1) > 1e-3) {
      observed[grid] += 1;
      if (bad_example.empty()) bad_example = to_string(*w);
      continue;
    }
    double phi = std::atan2(y, x);
    if (phi < 0) phi += kTwoPi;
    const int i = bin_index(z, -1, 1, bins_u), j = bin_index(phi, 0, kTwoPi, bins_v);
    observed[static_cast<size_t>(i) * bins_v + j] += 1;
  }
  const std::vector<double> integrals = bin_integrals(sphere_integrand(pdf), kSphereParameters, bins_u, bins_v);
  const auto label = [&](size_t bin) { return bin_label(kSphereParameters, bins_u, bins_v, bin, "cos(theta)", "phi"); };
  return finish(observed, integrals, "sphere", bad_example, label, options);
}

Chi2Result chi2_test_rect(const PointSampler& sample, const PointPdf& pdf, const Rect& domain,
                          const Chi2Options& options) {
  const int bins_u = options.bins_u, bins_v = options.bins_v;
  const size_t grid = static_cast<size_t>(bins_u) * bins_v;
  std::vector<double> observed(grid + 1, 0.0);
  std::string bad_example;
  UniformSource source(options.seed);
  for (int n = 0; n < options.sample_count; ++n) {
    const std::optional<Vec2> p = sample(source);
    if (!p) {
      observed[grid] += 1;
      continue;
    }
    const double x = p->x, y = p->y;
    if (!(x >= domain.x0 && x <= domain.x1 && y >= domain.y0 && y <= domain.y1)) {
      observed[grid] += 1;
      if (bad_example.empty()) bad_example = to_string(*p);
      continue;
    }
    const int i = bin_index(x, domain.x0, domain.x1, bins_u), j = bin_index(y, domain.y0, domain.y1, bins_v);
    observed[static_cast<size_t>(i) * bins_v + j] += 1;
  }
  const std::vector<double> integrals = bin_integrals(rect_integrand(pdf), domain, bins_u, bins_v);
  const auto label = [&](size_t bin) { return bin_label(domain, bins_u, bins_v, bin, "x", "y"); };
  return finish(observed, integrals, "rectangle", bad_example, label, options);
}

Chi2Result chi2_test_counts(std::span<const double> observed, std::span<const double> expected, double min_expected) {
  if (observed.size() != expected.size())
    throw std::invalid_argument("chi2_test_counts: observed and expected differ in length");
  double total = 0;
  for (double o : observed) total += o;
  std::ostringstream preface;
  preface << total << " samples in " << observed.size() << " categories\n";
  const auto label = [](size_t i) { return "category " + std::to_string(i); };
  return evaluate(observed, expected, label, min_expected, preface.str());
}

double chi2_p_value(double statistic, int dof) {
  if (dof <= 0) throw std::invalid_argument("chi2_p_value: dof must be positive");
  const double a = 0.5 * dof, x = 0.5 * statistic;
  if (!(x > 0)) return 1;
  if (std::isinf(x)) return 0;

  constexpr int kMaxIterations = 100000;
  constexpr double kEpsilon = 1e-15;
  // x^a e^-x / Gamma(a), common to both expansions, in logs to avoid overflow
  // at the thousands of degrees of freedom a binned test has.
  const double prefactor = std::exp(a * std::log(x) - x - std::lgamma(a));
  if (x < a + 1) {
    // Here the series for the lower function P(a, x) =
    // prefactor * sum_n x^n / (a (a+1) ... (a+n)) converges fast; Q = 1 - P.
    double term = 1 / a, sum = term;
    for (int n = 1; n < kMaxIterations && std::abs(term) > kEpsilon * sum; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return std::max(0.0, 1 - prefactor * sum);
  }
  // Beyond, Q(a, x) = prefactor / (x+1-a - 1(1-a) / (x+3-a - 2(2-a) / ...)),
  // evaluated by the modified Lentz method, which keeps Q accurate in the far
  // tail where 1 - P would round to zero.
  constexpr double kTiny = 1e-300;
  double b = x + 1 - a;
  double c = 1 / kTiny, d = 1 / b, h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1) < kEpsilon) break;
  }
  return prefactor * h;
}

double sidak_alpha(double alpha, int num_tests) {
  // 1 - (1 - alpha)^(1/n), without the cancellation of the direct form.
  return -std::expm1(std::log1p(-alpha) / num_tests);
}

double integrate_sphere(const DirectionPdf& pdf, int bins_cos_theta, int bins_phi) {
  double total = 0;
  for (double v : bin_integrals(sphere_integrand(pdf), kSphereParameters, bins_cos_theta, bins_phi)) total += v;
  return total;
}

double integrate_rect(const PointPdf& pdf, const Rect& domain, int bins_x, int bins_y) {
  double total = 0;
  for (double v : bin_integrals(rect_integrand(pdf), domain, bins_x, bins_y)) total += v;
  return total;
}

}  // namespace caustica::test

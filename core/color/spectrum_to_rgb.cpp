#include "core/color/spectrum_to_rgb.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "core/color/cie_tables.h"
#include "core/color/xyz_to_rec709.h"
#include "core/files/input_file.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

double parse_number(std::string_view text, const std::string& what) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw std::invalid_argument("cannot read '" + std::string(text.substr(0, 40)) + "' as " + what);
  if (!std::isfinite(v)) throw std::invalid_argument(what + " '" + std::string(text.substr(0, 40)) + "' is not finite");
  return v;
}

void add_sample(SampledSpectrum& s, double nm, double value) {
  if (!(nm > 0)) throw std::invalid_argument("wavelength " + std::to_string(nm) + " nm is not positive");
  if (!s.nm.empty() && !(nm > s.nm.back()))
    throw std::invalid_argument("wavelengths must increase, but " + std::to_string(nm) + " nm follows " +
                                std::to_string(s.nm.back()) + " nm");
  // Every spectrum a scene gives is a reflectance, a radiance or an
  // optical constant, none of which can be negative.
  if (value < 0)
    throw std::invalid_argument("value " + std::to_string(value) + " at " + std::to_string(nm) +
                                " nm is negative (a reflectance, radiance or optical constant cannot be)");
  s.nm.push_back(nm);
  s.values.push_back(value);
}

// One wavelength is no band: every other wavelength would read zero.
void check_band(const SampledSpectrum& s, const std::string& what) {
  if (s.nm.size() == 1)
    throw std::invalid_argument(what + " holds one wavelength only (" + std::to_string(s.nm.front()) +
                                " nm); a spectrum needs two or more, between which it is interpolated");
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

SampledSpectrum parse_spectrum_pairs(const std::string& text) {
  SampledSpectrum s;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string_view item = std::string_view(text).substr(start, end - start);
    const size_t colon = item.find(':');
    if (colon == std::string_view::npos)
      throw std::invalid_argument("expected wavelength:value, got '" + std::string(item.substr(0, 40)) + "'");
    add_sample(s, parse_number(item.substr(0, colon), "a wavelength"), parse_number(item.substr(colon + 1), "a value"));
    start = end + 1;
  }
  check_band(s, "the spectrum");
  return s;
}

SampledSpectrum read_spd_file(const std::filesystem::path& file) {
  if (const std::string problem = input_file_problem(file); !problem.empty())
    throw std::invalid_argument("spectrum file '" + file.string() + "' " + problem);
  std::ifstream in(file);
  if (!in) throw std::invalid_argument("cannot open spectrum file '" + file.string() + "'");
  SampledSpectrum s;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const size_t gap = line.find_first_of(" \t", first);
    try {
      if (gap == std::string::npos) throw std::invalid_argument("expected a wavelength and a value");
      add_sample(s, parse_number(std::string_view(line).substr(first, gap - first), "a wavelength"),
                 parse_number(std::string_view(line).substr(gap), "a value"));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(file.string() + ":" + std::to_string(line_number) + ": " + e.what());
    }
  }
  if (s.nm.empty()) throw std::invalid_argument("spectrum file '" + file.string() + "' holds no values");
  check_band(s, "spectrum file '" + file.string() + "'");
  return s;
}

SampledSpectrum blackbody(double kelvin) {
  // Planck: B = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1), per metre
  // of wavelength; 1e-9 of it per nanometre.
  constexpr double h = 6.62607015e-34, c = 2.99792458e8, k = 1.380649e-23;
  SampledSpectrum s;
  for (int nm = kCieFirstNm; nm <= kCieLastNm; nm += kCieStepNm) {
    const double lambda = nm * 1e-9;
    s.nm.push_back(nm);
    s.values.push_back(2 * h * c * c / std::pow(lambda, 5) / std::expm1(h * c / (lambda * k * kelvin)) * 1e-9);
  }
  return s;
}

Color spectrum_to_rgb(const SampledSpectrum& spectrum) {
  double xyz[3] = {0, 0, 0}, norm = 0;
  for (int nm = kCieFirstNm; nm <= kCieLastNm; ++nm) {
    const double s = spectrum.at(nm);
    xyz[0] += s * cie_table_at(kCieX, nm);
    xyz[1] += s * cie_table_at(kCieY, nm);
    xyz[2] += s * cie_table_at(kCieZ, nm);
    norm += cie_table_at(kCieY, nm);
  }
  const auto rgb = xyz_to_rec709({xyz[0] / norm, xyz[1] / norm, xyz[2] / norm});
  return Color(float(rgb[0]), float(rgb[1]), float(rgb[2]));
}

}  // namespace caustica

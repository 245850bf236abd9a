#include "core/bsdf/conductor_data.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>
#include <utility>

#include "core/registry/properties.h"
#include "core/spectral/metal_ior_tables.h"
#include "core/spectral/wavelengths.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

struct NamedConductor {
  const char* name;
  Color eta, k;
};

// RGB approximations of measured optical constants (eta, k), at about 650,
// 550 and 450 nm. The other named metals are read at exactly those.
constexpr double kChannelWavelengthsNm[3] = {650, 550, 450};
const NamedConductor kConductors[] = {
    {"Ag", {0.155f, 0.117f, 0.138f}, {4.828f, 3.122f, 2.147f}},
    {"Al", {1.657f, 0.880f, 0.521f}, {9.224f, 6.270f, 4.837f}},
    {"Au", {0.143f, 0.374f, 1.442f}, {3.983f, 2.385f, 1.603f}},
    {"Cu", {0.200f, 0.924f, 1.102f}, {3.912f, 2.452f, 2.142f}},
};

// A metal's measured eta and k as two spectra. A table that stops short of
// the range spectral transport samples is held at its last measured value
// (a spectrum is zero outside its samples, and eta = k = 0 is a mirror).
std::pair<std::shared_ptr<const SampledSpectrum>, std::shared_ptr<const SampledSpectrum>> measured(
    std::span<const MetalIorSample> table) {
  SampledSpectrum eta, k;
  const auto add = [&](double nm, const MetalIorSample& s) {
    eta.nm.push_back(nm);
    eta.values.push_back(s.eta);
    k.nm.push_back(nm);
    k.values.push_back(s.k);
  };
  if (table.front().nm > kMinWavelengthNm) add(kMinWavelengthNm, table.front());
  for (const MetalIorSample& s : table) add(s.nm, s);
  if (table.back().nm < kMaxWavelengthNm) add(kMaxWavelengthNm, table.back());
  return {std::make_shared<const SampledSpectrum>(std::move(eta)),
          std::make_shared<const SampledSpectrum>(std::move(k))};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::optional<ConductorIor> named_conductor(const std::string& name) {
  const std::span<const MetalIorSample> table = metal_ior_table(name);
  if (table.empty()) return std::nullopt;
  ConductorIor ior;
  std::tie(ior.eta_spectrum, ior.k_spectrum) = measured(table);
  const auto known = std::find_if(std::begin(kConductors), std::end(kConductors),
                                  [&](const NamedConductor& c) { return name == c.name; });
  if (known != std::end(kConductors)) {
    ior.eta = known->eta;
    ior.k = known->k;
  } else {
    // RGB transport reads the measurement at the wavelengths standing for
    // its channels.
    const auto channels = [](const SampledSpectrum& s) {
      return Color(float(s.at(kChannelWavelengthsNm[0])), float(s.at(kChannelWavelengthsNm[1])),
                   float(s.at(kChannelWavelengthsNm[2])));
    };
    ior.eta = channels(*ior.eta_spectrum);
    ior.k = channels(*ior.k_spectrum);
  }
  return ior;
}

std::vector<std::string> conductor_names() {
  std::vector<std::string> names;
  for (std::string_view name : metal_ior_names()) names.emplace_back(name);
  return names;
}

namespace {
namespace CAUSTICA_UNITY_ID {

ConductorIor absolute_ior(const Properties& props) {
  const std::string material = props.get_string("material");
  if (material == "none") {
    ConductorIor ior;
    ior.eta = props.get_color("eta");
    ior.k = props.get_color("k");
    for (int c = 0; c < 3; ++c) {
      if (!(ior.eta[c] >= 0)) throw props.error("eta", "must not be negative");
      if (!(ior.k[c] >= 0)) throw props.error("k", "must not be negative");
    }
    ior.eta_spectrum = props.spectrum("eta");
    ior.k_spectrum = props.spectrum("k");
    if (!ior.eta_spectrum != !ior.k_spectrum)
      throw props.error(ior.eta_spectrum ? "k" : "eta", "give eta and k both as spectra, or neither");
    ior.scene_spectra = ior.measured();
    return ior;
  }
  if (props.has("eta") || props.has("k"))
    throw props.error("material", "give either a material or eta and k, not both");
  const auto known = named_conductor(material);
  if (!known && metal_ior_unavailable(material))
    throw props.error("material", "Mitsuba's measured '" + material +
                                      "' is not included (its tables were not available to caustica); give its "
                                      "eta and k, as numbers or spectra");
  if (!known)
    throw props.error("material",
                      "unknown conductor '" + material + "' (known: none, " + join_names(conductor_names()) + ")");
  return *known;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

ConductorIor conductor_ior(const Properties& props) {
  ConductorIor ior = absolute_ior(props);
  const float outside = props.get_float("ext_eta");
  if (!(outside > 0 && std::isfinite(outside))) throw props.error("ext_eta", "must be positive");
  ior.eta = ior.eta / outside;
  ior.k = ior.k / outside;
  ior.outside = outside;
  return ior;
}

std::vector<ParamSpec> conductor_ior_params() {
  return {
      {"material", ParamType::String, "none",
       "measured metal by Mitsuba's name (Ag, Al, Au, Cu, Cr, W, TiN, ...), or none to use eta and k"},
      {"eta", ParamType::Color, "0", "real part of the complex index of refraction, per channel or as a spectrum"},
      {"k", ParamType::Color, "1", "imaginary part (absorption) of the complex index, per channel or as a spectrum"},
      {"ext_eta", ParamType::Float, "1", "index of the outside, which eta and k are divided by (Mitsuba 0.x)"}};
}

}  // namespace caustica

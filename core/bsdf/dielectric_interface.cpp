#include "core/bsdf/dielectric_interface.h"

#include <cmath>
#include <stdexcept>

#include "core/bsdf/ior.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

std::optional<Dispersion> read_dispersion(const Properties& props) {
  const std::string text = props.get_string("dispersion");
  if (text == "none") return std::nullopt;
  if (props.has("int_ior")) throw props.error("dispersion", "give either int_ior or a dispersion, not both");
  try {
    Dispersion d = Dispersion::parse(text);
    for (double nm = kMinWavelengthNm; nm <= kMaxWavelengthNm; nm += 1) {
      const double n = d.ior(nm);
      if (!(n > 0 && std::isfinite(n)))
        throw std::invalid_argument("its index at " + std::to_string(int(nm)) + " nm is " + std::to_string(n) +
                                    ", not a positive number");
    }
    return d;
  } catch (const std::invalid_argument& e) {
    throw props.error("dispersion", e.what());
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

DielectricInterface::DielectricInterface(const Properties& props, bool reads_dispersion)
    : ext_ior(read_ior(props, "ext_ior")),
      dispersion(reads_dispersion ? read_dispersion(props) : std::nullopt),
      reflectance(read_reflectance(props, "specular_reflectance")),
      transmittance(read_reflectance(props, "specular_transmittance")) {
  eta = float((dispersion ? dispersion->ior_d() : read_ior(props, "int_ior")) / ext_ior);
}

ParamSpec dispersion_param() {
  return {"dispersion", ParamType::String, "none",
          "an inside index varying with wavelength, in place of int_ior: bk7, fused silica, diamond, water, sf11, "
          "\"cauchy: A, B, ...\" (um) or \"sellmeier: B1, C1, B2, C2, ...\" (C in um^2)"};
}

}  // namespace caustica

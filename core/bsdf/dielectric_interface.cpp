#include "core/bsdf/dielectric_interface.h"

#include "core/bsdf/ior.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {

DielectricInterface::DielectricInterface(const Properties& props)
    : eta(read_ior(props, "int_ior") / read_ior(props, "ext_ior")),
      reflectance(read_reflectance(props, "specular_reflectance")),
      transmittance(read_reflectance(props, "specular_transmittance")) {}

}  // namespace caustica

#include "core/bsdf/dielectric_interface.h"

#include "core/registry/properties.h"

namespace caustica {

DielectricInterface::DielectricInterface(const Properties& props)
    : eta(props.get_ior("int_ior") / props.get_ior("ext_ior")),
      reflectance(props.get_texture("specular_reflectance")),
      transmittance(props.get_texture("specular_transmittance")) {}

}  // namespace caustica

#pragma once

#include <memory>

#include "core/texture/texture.h"

namespace caustica {

class Properties;

// What every dielectric material reads from its parameters: the relative
// index of refraction int_ior / ext_ior and the textures that scale the
// reflected and the transmitted light.
struct DielectricInterface {
  explicit DielectricInterface(const Properties& props);

  float eta;
  std::shared_ptr<Texture> reflectance, transmittance;
};

}  // namespace caustica

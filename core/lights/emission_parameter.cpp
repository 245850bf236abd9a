#include "core/lights/emission_parameter.h"

#include <cmath>

#include "core/texture/texture_parameter.h"

namespace caustica {

Color read_emission(const Properties& props, const std::string& name) {
  const Color c = props.get_color(name);
  for (float v : {c.r, c.g, c.b}) {
    if (!std::isfinite(v)) throw props.error(name, "must be finite");
    if (v < 0) throw props.error(name, "must not be negative");
  }
  return c;
}

std::shared_ptr<Texture> read_emission_texture(const Properties& props, const std::string& name) {
  auto texture = read_texture(props, name);
  const ValueRange range = texture->range();
  if (!std::isfinite(range.lowest) || !std::isfinite(range.highest)) throw props.error(name, "must be finite");
  if (range.lowest < 0) throw props.error(name, "must not be negative");
  return texture;
}

}  // namespace caustica

#include "core/lights/emission_parameter.h"

#include <cmath>

namespace caustica {

Color read_emission(const Properties& props, const std::string& name) {
  const Color c = props.get_color(name);
  for (float v : {c.r, c.g, c.b}) {
    if (!std::isfinite(v)) throw props.error(name, "must be finite");
    if (v < 0) throw props.error(name, "must not be negative");
  }
  return c;
}

}  // namespace caustica

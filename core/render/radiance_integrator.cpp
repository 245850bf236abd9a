#include "core/render/radiance_integrator.h"

namespace caustica {

int64_t read_max_depth(const Properties& props) {
  const int64_t d = props.get_int("max_depth");
  if (d < -1) throw props.error("max_depth", "must be -1 (unlimited) or at least 0");
  return d;
}

}  // namespace caustica

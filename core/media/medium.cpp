#include "core/media/medium.h"

#include "core/registry/properties.h"

namespace caustica {

void Medium::read_common(const Properties& props) {
  phase_ = props.child<PhaseFunction>("phase");
  if (!phase_) phase_ = Registry::instance().create_default<PhaseFunction>("phase", "isotropic", props.where());
  sample_emitters_ = props.get_bool("sample_emitters");
}

}  // namespace caustica

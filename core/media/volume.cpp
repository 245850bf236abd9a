#include "core/media/volume.h"

#include "core/media/constant_volume.h"
#include "core/registry/properties.h"

namespace caustica {

std::shared_ptr<const Volume> read_volume(const Properties& props, const std::string& name) {
  const PropertyValue v = props.value(name, ParamType::Volume);
  if (v.kind == ValueKind::Object)
    return std::dynamic_pointer_cast<const Volume>(std::get<ObjectValue>(v.value).object);
  const Color c = as_color(v);
  for (int i = 0; i < 3; ++i)
    if (!(c[i] >= 0) || !std::isfinite(c[i])) throw props.error(name, "must be finite and at least 0 in every channel");
  return make_constant_volume(c);
}

}  // namespace caustica

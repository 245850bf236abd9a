#include "core/texture/texture_parameter.h"

namespace caustica {

std::shared_ptr<Texture> read_texture(const Properties& props, const std::string& name) {
  const PropertyValue v = props.value(name, ParamType::Texture);
  if (v.kind == ValueKind::Object) return std::dynamic_pointer_cast<Texture>(std::get<ObjectValue>(v.value).object);
  return std::make_shared<ConstantTexture>(as_color(v));
}

}  // namespace caustica

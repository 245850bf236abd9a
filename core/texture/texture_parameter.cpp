#include "core/texture/texture_parameter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

std::string number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(v));
  return text;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::shared_ptr<Texture> read_texture(const Properties& props, const std::string& name) {
  const PropertyValue v = props.value(name, ParamType::Texture);
  if (v.kind == ValueKind::Object) return std::dynamic_pointer_cast<Texture>(std::get<ObjectValue>(v.value).object);
  return std::make_shared<ConstantTexture>(as_color(v), v.spectrum);
}

std::shared_ptr<Texture> read_nonnegative_texture(const Properties& props, const std::string& name) {
  auto texture = read_texture(props, name);
  const ValueRange range = texture->range();
  if (!std::isfinite(range.lowest) || !std::isfinite(range.highest)) throw props.error(name, "must be finite");
  if (range.lowest < 0) throw props.error(name, "must not be negative (it goes down to " + number(range.lowest) + ")");
  return texture;
}

std::shared_ptr<Texture> read_reflectance(const Properties& props, const std::string& name) {
  auto texture = read_nonnegative_texture(props, name);
  const ValueRange range = texture->range();
  if (range.highest > 1)
    props.warn(name, "goes up to " + number(range.highest) +
                         ": a surface that reflects more light than it receives gains energy");
  return texture;
}

std::shared_ptr<Texture> read_fraction(const Properties& props, const std::string& name) {
  auto texture = read_texture(props, name);
  const ValueRange range = texture->range();
  if (!(range.lowest >= 0 && range.highest <= 1))
    throw props.error(name,
                      "must lie in [0, 1] (it spans " + number(range.lowest) + " to " + number(range.highest) + ")");
  return texture;
}

float eval_fraction(const Texture& texture, Vec2 uv, float fallback) {
  const float a = texture.eval(uv).luminance();
  return std::isfinite(a) ? std::clamp(a, 0.0f, 1.0f) : fallback;
}

}  // namespace caustica

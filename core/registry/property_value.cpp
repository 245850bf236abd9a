#include "core/registry/property_value.h"

#include <charconv>
#include <cmath>
#include <vector>

namespace caustica {

const char* to_string(ValueKind k) {
  switch (k) {
    case ValueKind::Boolean:
      return "boolean";
    case ValueKind::Integer:
      return "integer";
    case ValueKind::Float:
      return "float";
    case ValueKind::String:
      return "string";
    case ValueKind::Rgb:
      return "rgb";
    case ValueKind::Point:
      return "point";
    case ValueKind::Vector:
      return "vector";
    case ValueKind::Transform:
      return "transform";
    case ValueKind::Object:
      return "object";
  }
  return "?";
}

std::vector<double> parse_numbers(const std::string& text, const SourceLocation& where, const char* what) {
  std::vector<double> out;
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    while (p < end && (*p == ',' || std::isspace(static_cast<unsigned char>(*p)))) ++p;
    if (p == end) break;
    // An explicit sign, as Mitsuba's files write (+0.3); from_chars takes only '-'.
    if (*p == '+' && p + 1 < end && *(p + 1) != '-' && *(p + 1) != '+') ++p;
    double v = 0;
    auto [next, ec] = std::from_chars(p, end, v);
    if (ec != std::errc() || !std::isfinite(v))
      throw SceneError(where, std::string("cannot parse '") + text + "' as " + what);
    out.push_back(v);
    p = next;
  }
  return out;
}

PropertyValue parse_value_text(ValueKind kind, const std::string& text, const SourceLocation& where) {
  PropertyValue v{kind, {}, where};
  switch (kind) {
    case ValueKind::Boolean:
      if (text == "true")
        v.value = true;
      else if (text == "false")
        v.value = false;
      else
        throw SceneError(where, "cannot parse '" + text + "' as boolean (expected true or false)");
      break;
    case ValueKind::Integer: {
      int64_t i = 0;
      const char* begin = text.data() + (text.size() > 1 && text[0] == '+' && text[1] != '-' ? 1 : 0);
      auto [next, ec] = std::from_chars(begin, text.data() + text.size(), i);
      if (ec != std::errc() || next != text.data() + text.size())
        throw SceneError(where, "cannot parse '" + text + "' as integer");
      v.value = i;
      break;
    }
    case ValueKind::Float: {
      const auto n = parse_numbers(text, where, "float");
      if (n.size() != 1) throw SceneError(where, "cannot parse '" + text + "' as float");
      v.value = n[0];
      break;
    }
    case ValueKind::String:
      v.value = text;
      break;
    case ValueKind::Rgb: {
      const auto n = parse_numbers(text, where, "rgb");
      if (n.size() == 1)
        v.value = Color(float(n[0]));
      else if (n.size() == 3)
        v.value = Color(float(n[0]), float(n[1]), float(n[2]));
      else
        throw SceneError(where, "cannot parse '" + text + "' as rgb (expected 1 or 3 numbers)");
      break;
    }
    case ValueKind::Point:
    case ValueKind::Vector: {
      const auto n = parse_numbers(text, where, to_string(kind));
      if (n.size() != 3)
        throw SceneError(where, "cannot parse '" + text + "' as " + to_string(kind) + " (expected 3 numbers)");
      v.value = Vec3d(n[0], n[1], n[2]);
      break;
    }
    case ValueKind::Transform:
      if (!text.empty()) throw SceneError(where, "a transform default must be empty (identity)");
      v.value = Transform();
      break;
    case ValueKind::Object:
      throw SceneError(where, "an object has no text form");
  }
  return v;
}

bool kind_fits(ValueKind given, ParamType wanted, const std::string& object_category) {
  switch (wanted) {
    case ParamType::Boolean:
      return given == ValueKind::Boolean;
    case ParamType::Integer:
      return given == ValueKind::Integer;
    case ParamType::Float:
      return given == ValueKind::Float || given == ValueKind::Integer;
    case ParamType::String:
      return given == ValueKind::String;
    case ParamType::Color:
      return given == ValueKind::Rgb || given == ValueKind::Float || given == ValueKind::Integer;
    case ParamType::Texture:
      return given == ValueKind::Rgb || given == ValueKind::Float || given == ValueKind::Integer ||
             (given == ValueKind::Object && object_category == "texture");
    case ParamType::Point:
      // Exporters write a point light's position as a <vector> (Blender's).
      return given == ValueKind::Point || given == ValueKind::Vector;
    case ParamType::Vector:
      return given == ValueKind::Vector || given == ValueKind::Point;
    case ParamType::Transform:
      return given == ValueKind::Transform;
    case ParamType::Ior:
      return given == ValueKind::Float || given == ValueKind::Integer || given == ValueKind::String;
    case ParamType::Medium:
      return given == ValueKind::Object && object_category == "medium";
    case ParamType::Volume:
      return given == ValueKind::Rgb || given == ValueKind::Float || given == ValueKind::Integer ||
             (given == ValueKind::Object && object_category == "volume");
  }
  return false;
}

ValueKind default_kind(ParamType t) {
  switch (t) {
    case ParamType::Boolean:
      return ValueKind::Boolean;
    case ParamType::Integer:
      return ValueKind::Integer;
    case ParamType::Float:
      return ValueKind::Float;
    case ParamType::String:
      return ValueKind::String;
    case ParamType::Color:
    case ParamType::Texture:
    case ParamType::Volume:
      return ValueKind::Rgb;
    case ParamType::Point:
      return ValueKind::Point;
    case ParamType::Vector:
      return ValueKind::Vector;
    case ParamType::Transform:
      return ValueKind::Transform;
    case ParamType::Ior:
      return ValueKind::String;
    case ParamType::Medium:
      return ValueKind::Object;
  }
  return ValueKind::Float;
}

Color as_color(const PropertyValue& v) {
  switch (v.kind) {
    case ValueKind::Integer:
      return Color(float(std::get<int64_t>(v.value)));
    case ValueKind::Float:
      return Color(float(std::get<double>(v.value)));
    default:
      return std::get<Color>(v.value);
  }
}

}  // namespace caustica

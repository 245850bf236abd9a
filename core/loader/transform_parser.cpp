#include "core/loader/transform_parser.h"

#include <stdexcept>
#include <vector>

#include "core/registry/property_value.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Transforms are read in double: a translation of 1e7 keeps its fraction.
double number(const XmlNode& node, const char* attr, double fallback) {
  const std::string* v = node.attribute(attr);
  return v ? std::get<double>(parse_value_text(ValueKind::Float, *v, node.where).value) : fallback;
}

Vec3d triple(const XmlNode& node, const char* attr) {
  const std::string* v = node.attribute(attr);
  if (!v) throw SceneError(node.where, "<" + node.tag + "> needs a '" + attr + "' attribute");
  return std::get<Vec3d>(parse_value_text(ValueKind::Vector, *v, node.where).value);
}

// value="x, y, z" or x/y/z attributes, each defaulting to `fallback`.
Vec3d xyz(const XmlNode& node, double fallback) {
  if (node.attribute("value")) return triple(node, "value");
  return {number(node, "x", fallback), number(node, "y", fallback), number(node, "z", fallback)};
}

Transform parse_step(const XmlNode& step) {
  if (step.tag == "translate") {
    step.check_attributes({"x", "y", "z", "value"});
    return Transform::translate(xyz(step, 0));
  }
  if (step.tag == "scale") {
    step.check_attributes({"x", "y", "z", "value"});
    if (const std::string* v = step.attribute("value"); v && v->find_first_of(", ") == std::string::npos) {
      const double s = number(step, "value", 1);
      return Transform::scale({s, s, s});
    }
    return Transform::scale(xyz(step, 1));
  }
  if (step.tag == "rotate") {
    step.check_attributes({"x", "y", "z", "value", "angle"});
    const Vec3d axis = xyz(step, 0);
    if (axis == Vec3d()) throw SceneError(step.where, "<rotate> needs a non-zero axis");
    return Transform::rotate(axis, number(step, "angle", 0));
  }
  if (step.tag == "matrix") {
    step.check_attributes({"value"});
    const std::string* v = step.attribute("value");
    if (!v) throw SceneError(step.where, "<matrix> needs a 'value' attribute");
    const std::vector<double> values = parse_numbers(*v, step.where, "matrix");
    Matrix4 m = Matrix4::identity();
    if (values.size() != 16)
      throw SceneError(step.where, "<matrix> needs 16 numbers (row-major 4x4), found " + std::to_string(values.size()));
    for (int i = 0; i < 16; ++i) m.m[i / 4][i % 4] = values[i];
    return Transform(m);
  }
  if (step.tag == "lookat") {
    step.check_attributes({"origin", "target", "up"});
    const Vec3d up = step.attribute("up") ? triple(step, "up") : Vec3d(0, 1, 0);
    return Transform::look_at(triple(step, "origin"), triple(step, "target"), up);
  }
  throw SceneError(step.where,
                   "unknown transform step <" + step.tag + "> (accepted: translate, rotate, scale, matrix, lookat)");
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Transform parse_transform(const XmlNode& node) {
  Transform t;
  for (const XmlNode& step : node.children) {
    try {
      t = parse_step(step) * t;
    } catch (const std::invalid_argument& e) {  // a singular matrix, a degenerate lookat
      throw SceneError(step.where, e.what());
    }
  }
  return t;
}

}  // namespace caustica

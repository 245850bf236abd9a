#include "core/registry/properties.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/registry/file_resolver.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

std::string plugin_name(const PluginInfo& info) { return info.category + " '" + info.name + "'"; }

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void Properties::set(const std::string& name, PropertyValue value) {
  const ParamSpec* spec = info_->param(name);
  if (!spec) {
    std::vector<std::string> accepted;
    for (const auto& p : info_->params) accepted.push_back(p.name);
    throw SceneError(value.where, "unknown parameter '" + name + "' for " + plugin_name(*info_) +
                                      " (accepted: " + join_names(accepted) + ")");
  }
  const std::string category =
      value.kind == ValueKind::Object ? std::get<ObjectValue>(value.value).category : std::string();
  if (!kind_fits(value.kind, spec->type, category)) {
    const std::string given = value.kind == ValueKind::Object ? category : to_string(value.kind);
    throw SceneError(value.where, "parameter '" + name + "' of " + plugin_name(*info_) + " must be " +
                                      to_string(spec->type) + ", not " + given);
  }
  if (find(name)) throw SceneError(value.where, "parameter '" + name + "' is given twice");
  values_.emplace_back(name, std::move(value));
}

void Properties::add_child(ObjectValue child, const SourceLocation& where, const std::string& name) {
  const auto& accepted = info_->child_categories;
  if (std::find(accepted.begin(), accepted.end(), child.category) == accepted.end()) {
    // An object this plugin takes only as a parameter (a texture as a
    // reflectance): say which names it goes by.
    std::vector<std::string> params;
    for (const ParamSpec& spec : info_->params)
      if (kind_fits(ValueKind::Object, spec.type, child.category)) params.push_back(spec.name);
    const std::string place = plugin_name(*info_);
    if (params.empty())
      throw SceneError(
          where, place + " does not take a nested <" + child.category + "> (accepted: " + join_names(accepted) + ")");
    if (name.empty())
      throw SceneError(where, place + " takes a nested <" + child.category +
                                  "> only as a parameter: name it (name=\"...\"): " + join_names(params));
    throw SceneError(where, place + " has no parameter '" + name + "' that takes a <" + child.category +
                                "> (those that do: " + join_names(params) + ")");
  }
  children_.emplace_back(std::move(child), where);
  child_names_.push_back(name);
}

const PropertyValue* Properties::find(const std::string& name) const {
  for (const auto& [key, value] : values_)
    if (key == name) return &value;
  return nullptr;
}

SceneError Properties::error(const std::string& name, const std::string& problem) const {
  const PropertyValue* v = find(name);
  return SceneError(v ? v->where : where_, "parameter '" + name + "' of " + plugin_name(*info_) + ": " + problem);
}

void Properties::warn(const std::string& name, const std::string& problem) const {
  const std::string message = error(name, problem).what();
  if (warnings_)
    warnings_->push_back(message);
  else
    std::fprintf(stderr, "caustica: warning: %s\n", message.c_str());
}

PropertyValue Properties::value(const std::string& name, ParamType wanted) const {
  const ParamSpec* spec = info_->param(name);
  if (!spec || spec->type != wanted)
    throw std::logic_error(plugin_name(*info_) + " reads undeclared parameter " + name + " as " + to_string(wanted));
  if (const PropertyValue* v = find(name)) return *v;
  if (!spec->default_value) throw SceneError(where_, plugin_name(*info_) + " requires parameter '" + name + "'");
  return parse_value_text(default_kind(wanted), *spec->default_value, where_);
}

namespace {
namespace CAUSTICA_UNITY_ID {

std::string bool_text(bool b) { return b ? "true" : "false"; }

float as_float(const PropertyValue& v) {
  return v.kind == ValueKind::Integer ? float(std::get<int64_t>(v.value)) : float(std::get<double>(v.value));
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void Properties::record(const std::string& name, std::string text) const {
  for (auto& [key, value] : read_)
    if (key == name) {
      value = std::move(text);
      return;
    }
  read_.emplace_back(name, std::move(text));
}

bool Properties::get_bool(const std::string& name) const {
  const bool b = std::get<bool>(value(name, ParamType::Boolean).value);
  record(name, bool_text(b));
  return b;
}

int64_t Properties::get_int(const std::string& name) const {
  const int64_t i = std::get<int64_t>(value(name, ParamType::Integer).value);
  record(name, std::to_string(i));
  return i;
}

int64_t Properties::get_int_or(const std::string& name, int64_t fallback) const {
  const int64_t i = has(name) ? std::get<int64_t>(value(name, ParamType::Integer).value) : fallback;
  record(name, std::to_string(i));
  return i;
}

float Properties::get_float(const std::string& name) const {
  const float f = as_float(value(name, ParamType::Float));
  record(name, std::to_string(f));
  return f;
}

std::string Properties::get_string(const std::string& name) const {
  std::string text = std::get<std::string>(value(name, ParamType::String).value);
  record(name, text);
  return text;
}

std::vector<std::pair<std::string, std::string>> Properties::effective_parameters() const {
  // A parameter the plugin never read is read here, so that every value is
  // recorded the one way the getters record it.
  for (const ParamSpec& spec : info_->params) {
    const bool read = std::any_of(read_.begin(), read_.end(), [&](const auto& r) { return r.first == spec.name; });
    if (read || (!has(spec.name) && !spec.default_value)) continue;
    if (spec.type == ParamType::Boolean) get_bool(spec.name);
    if (spec.type == ParamType::Integer) get_int(spec.name);
    if (spec.type == ParamType::Float) get_float(spec.name);
    if (spec.type == ParamType::String) get_string(spec.name);
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (const ParamSpec& spec : info_->params)
    for (const auto& r : read_)
      if (r.first == spec.name) out.push_back(r);
  return out;
}

std::filesystem::path Properties::get_path(const std::string& name) const {
  const PropertyValue v = value(name, ParamType::String);
  const std::filesystem::path file = std::get<std::string>(v.value);
  if (files_) return files_->resolve(file, v.where.file);
  if (file.is_absolute()) return file;
  return std::filesystem::path(v.where.file).parent_path() / file;
}

Color Properties::get_color(const std::string& name) const { return as_color(value(name, ParamType::Color)); }

Vec3d Properties::get_point(const std::string& name) const {
  return std::get<Vec3d>(value(name, ParamType::Point).value);
}

Vec3 Properties::get_vector(const std::string& name) const {
  const Vec3d v = std::get<Vec3d>(value(name, ParamType::Vector).value);
  return {float(v.x), float(v.y), float(v.z)};
}

Transform Properties::get_transform(const std::string& name) const {
  const Transform t = std::get<Transform>(value(name, ParamType::Transform).value);
  if (name != "to_world" || render_origin_ == Vec3d()) return t;
  return Transform::translate(-render_origin_) * t;
}

}  // namespace caustica

#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/math/color.h"
#include "core/math/transform.h"
#include "core/registry/property_value.h"
#include "core/registry/registry.h"

namespace caustica {

class FileResolver;

// The parameters and nested objects handed to one plugin's constructor.
// Getters fall back to the default the plugin declared, so a default is
// written once, in the registration.
class Properties {
 public:
  Properties(const PluginInfo& info, SourceLocation where) : info_(&info), where_(std::move(where)) {}

  // Loader side; each checks the value against the declaration and throws
  // SceneError naming the file, line and what is accepted.
  void set(const std::string& name, PropertyValue value);
  // `name`, if the element had one, is named in the error for an object
  // the plugin takes only as a parameter of another name.
  void add_child(ObjectValue child, const SourceLocation& where, const std::string& name = "");

  const PluginInfo& info() const { return *info_; }
  // The values set, in the order they were given.
  const std::vector<std::pair<std::string, PropertyValue>>& values() const { return values_; }
  const SourceLocation& where() const { return where_; }
  bool has(const std::string& name) const { return find(name) != nullptr; }
  // The spectrum a colour parameter was given as, if it was (null otherwise).
  std::shared_ptr<const SampledSpectrum> spectrum(const std::string& name) const {
    const PropertyValue* v = find(name);
    return v ? v->spectrum : nullptr;
  }

  // Each getter records the value it returns as the parameter's effective
  // value (effective_parameters()).
  bool get_bool(const std::string& name) const;
  int64_t get_int(const std::string& name) const;
  // The value given, else `fallback` (not the declared default): for
  // parameters whose default is another parameter's value.
  int64_t get_int_or(const std::string& name, int64_t fallback) const;
  float get_float(const std::string& name) const;
  std::string get_string(const std::string& name) const;
  // A string naming a file, found by the resolver set (else beside the scene
  // file it was written in).
  std::filesystem::path get_path(const std::string& name) const;
  Color get_color(const std::string& name) const;
  // In double: a point far from the origin keeps its precision until
  // get_transform("to_world") has moved it next to the camera.
  Vec3d get_point(const std::string& name) const;
  Vec3 get_vector(const std::string& name) const;
  // A `to_world` comes back mapping into render space: world space moved so
  // that set_render_origin()'s point (the camera) is its origin.
  Transform get_transform(const std::string& name) const;

  // The object given as parameter `name`, null where none was given.
  template <class T>
  std::shared_ptr<T> get_object(const std::string& name) const {
    const PropertyValue* v = find(name);
    return v ? std::dynamic_pointer_cast<T>(std::get<ObjectValue>(v->value).object) : nullptr;
  }

  template <class T>
  std::vector<std::shared_ptr<T>> children(const std::string& category) const {
    std::vector<std::shared_ptr<T>> out;
    for (const auto& [child, where] : children_)
      if (child.category == category) out.push_back(std::dynamic_pointer_cast<T>(child.object));
    return out;
  }
  // The same, each with where it was written.
  template <class T>
  std::vector<std::pair<std::shared_ptr<T>, SourceLocation>> children_at(const std::string& category) const {
    std::vector<std::pair<std::shared_ptr<T>, SourceLocation>> out;
    for (const auto& [child, where] : children_)
      if (child.category == category) out.emplace_back(std::dynamic_pointer_cast<T>(child.object), where);
    return out;
  }
  // The same, each with the name the element gave it ("" for none).
  template <class T>
  std::vector<std::pair<std::shared_ptr<T>, std::string>> children_named(const std::string& category) const {
    std::vector<std::pair<std::shared_ptr<T>, std::string>> out;
    for (size_t i = 0; i < children_.size(); ++i)
      if (children_[i].first.category == category)
        out.emplace_back(std::dynamic_pointer_cast<T>(children_[i].first.object), child_names_[i]);
    return out;
  }
  // At most one nested object of `category`; null if there is none.
  template <class T>
  std::shared_ptr<T> child(const std::string& category) const {
    auto all = children<T>(category);
    if (all.size() > 1) throw SceneError(where_, info_->category + " '" + info_->name + "' takes one " + category);
    return all.empty() ? nullptr : all.front();
  }

  // The value of a parameter of type `wanted`: the one given, else the
  // declared default (parsed), else a SceneError as the parameter is required.
  PropertyValue value(const std::string& name, ParamType wanted) const;

  // The effective value of every scalar (boolean, integer, float, string)
  // parameter the plugin declares, in declaration order: what its getters
  // returned, else the value given or declared; required ones never given
  // are left out.
  std::vector<std::pair<std::string, std::string>> effective_parameters() const;

  // An error about parameter `name`, placed where it was written (or at the
  // plugin if it was left at its default).
  SceneError error(const std::string& name, const std::string& problem) const;
  // A warning, placed as error() places errors, for a value that is
  // accepted but probably not what the author meant. It goes to the list
  // set_warnings() named (the loader's), else to standard error.
  void warn(const std::string& name, const std::string& problem) const;
  void set_warnings(std::vector<std::string>* warnings) { warnings_ = warnings; }
  void set_render_origin(Vec3d origin) { render_origin_ = origin; }
  void set_resolver(const FileResolver* files) { files_ = files; }

 private:
  const PropertyValue* find(const std::string& name) const;

  const PluginInfo* info_;
  SourceLocation where_;
  std::vector<std::pair<std::string, PropertyValue>> values_;
  std::vector<std::pair<ObjectValue, SourceLocation>> children_;
  std::vector<std::string> child_names_;                           // the name each of children_ was given, or ""
  mutable std::vector<std::pair<std::string, std::string>> read_;  // effective values, as the getters returned them
  std::vector<std::string>* warnings_ = nullptr;
  Vec3d render_origin_;
  const FileResolver* files_ = nullptr;
  void record(const std::string& name, std::string value) const;
};

template <class T>
std::shared_ptr<T> Registry::create_default(const std::string& category, const std::string& name,
                                            const SourceLocation& where) const {
  const PluginInfo* info = find(category, name);
  if (!info) throw SceneError(where, "no " + category + " plugin named '" + name + "'");
  return std::dynamic_pointer_cast<T>(info->create(Properties(*info, where)));
}

}  // namespace caustica

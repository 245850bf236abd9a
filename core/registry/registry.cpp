#include "core/registry/registry.h"

#include <stdexcept>

#include "core/registry/category_params.h"
#include "core/registry/ignored_params.h"

namespace caustica {

const char* to_string(ParamType t) {
  switch (t) {
    case ParamType::Boolean:
      return "boolean";
    case ParamType::Integer:
      return "integer";
    case ParamType::Float:
      return "float";
    case ParamType::String:
      return "string";
    case ParamType::Color:
      return "rgb";
    case ParamType::Texture:
      return "texture";
    case ParamType::Point:
      return "point";
    case ParamType::Vector:
      return "vector";
    case ParamType::Transform:
      return "transform";
    case ParamType::Ior:
      return "float or IOR name";
    case ParamType::Medium:
      return "medium";
    case ParamType::Volume:
      return "volume";
  }
  return "?";
}

const ParamSpec* PluginInfo::param(const std::string& param_name) const {
  for (const ParamSpec& p : params)
    if (p.name == param_name) return &p;
  return nullptr;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& s : names) out += (out.empty() ? "" : ", ") + s;
  return out.empty() ? "none" : out;
}

Registry& Registry::instance() {
  static Registry registry;
  return registry;
}

bool Registry::add(PluginInfo info) {
  for (const CategoryParams& shared : category_params())
    if (shared.category == info.category) {
      info.params.insert(info.params.end(), shared.params.begin(), shared.params.end());
      info.child_categories.insert(info.child_categories.end(), shared.child_categories.begin(),
                                   shared.child_categories.end());
    }
  for (const IgnoredParam& ignored : ignored_params())
    if (ignored.category == info.category && !info.param(ignored.spec.name)) {
      info.params.push_back(ignored.spec);
      info.ignored.push_back(ignored.spec.name);
    }
  auto key = std::make_pair(info.category, info.name);
  if (plugins_.count(key)) throw std::logic_error("plugin registered twice: " + info.category + " " + info.name);
  plugins_.emplace(std::move(key), std::move(info));
  return true;
}

const PluginInfo* Registry::find(const std::string& category, const std::string& name) const {
  auto it = plugins_.find({category, name});
  return it == plugins_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::categories() const {
  std::vector<std::string> out;
  for (const auto& [key, info] : plugins_)
    if (out.empty() || out.back() != key.first) out.push_back(key.first);
  return out;
}

std::vector<std::string> Registry::names(const std::string& category) const {
  std::vector<std::string> out;
  for (const auto& [key, info] : plugins_)
    if (key.first == category) out.push_back(key.second);
  return out;
}

}  // namespace caustica

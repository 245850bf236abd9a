#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/errors/scene_error.h"
#include "core/registry/param_spec.h"
#include "core/registry/plugin.h"

namespace caustica {

class Properties;

// What a plugin accepts: its parameters and the kinds of nested objects
// (categories such as "bsdf" or "emitter") it takes.
struct PluginInfo {
  std::string category;  // the XML tag: integrator, sensor, film, sampler, rfilter, shape, bsdf, emitter, texture
  std::string name;      // the type="..." value
  std::vector<ParamSpec> params;
  std::vector<std::string> child_categories;
  std::function<std::shared_ptr<Plugin>(const Properties&)> create;
  // The category's ignored parameters (ignored_params.h) the registry added
  // because the plugin does not declare them itself.
  std::vector<std::string> ignored;

  const ParamSpec* param(const std::string& param_name) const;
};

class Registry {
 public:
  static Registry& instance();

  // Returns true so that registration can initialise a namespace-scope constant.
  bool add(PluginInfo info);
  const PluginInfo* find(const std::string& category, const std::string& name) const;
  std::vector<std::string> names(const std::string& category) const;
  // Every category that has a plugin, in alphabetical order.
  std::vector<std::string> categories() const;
  // The plugin with every parameter at its default, for objects a scene may
  // leave out (a film's filter, a shape's material). `where` is blamed for errors.
  template <class T>
  std::shared_ptr<T> create_default(const std::string& category, const std::string& name,
                                    const SourceLocation& where) const;

 private:
  std::map<std::pair<std::string, std::string>, PluginInfo> plugins_;
};

// Registers a plugin from its own translation unit:
//   CAUSTICA_REGISTER_PLUGIN(DiffuseBsdf, "bsdf", "diffuse", {{params...}}, {child categories});
// "a, b, c", or "none" for an empty list: for messages that list what is accepted.
std::string join_names(const std::vector<std::string>& names);

// The plugin made records its effective parameters (Plugin::parameters()).
#define CAUSTICA_REGISTER_PLUGIN(Class, category, name, ...)                                             \
  [[maybe_unused]] static const bool caustica_registered_##Class = ::caustica::Registry::instance().add( \
      ::caustica::PluginInfo{category,                                                                   \
                             name,                                                                       \
                             __VA_ARGS__,                                                                \
                             [](const ::caustica::Properties& props) {                                   \
                               auto plugin = std::make_shared<Class>(props);                             \
                               plugin->set_parameters(name, props.effective_parameters());               \
                               return std::shared_ptr<::caustica::Plugin>(std::move(plugin));            \
                             },                                                                          \
                             {}})

}  // namespace caustica

#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/color/tone_operator.h"
#include "core/registry/property_value.h"
#include "core/render/integrator.h"
#include "core/scene/scene.h"

namespace caustica {

using Defines = std::map<std::string, std::string>;

// -D values, each "name=value", as the command line gives them.
Defines parse_defines(const std::vector<std::string>& items);

// Parameter values as a scene file gave them, in order.
using GivenValues = std::vector<std::pair<std::string, PropertyValue>>;

// A scene file's contents: the scene, and the render settings it names.
struct LoadedScene {
  std::shared_ptr<Scene> scene;
  std::shared_ptr<const Integrator> integrator;  // the file's <integrator>, or path with its defaults
  GivenValues integrator_values;                 // the parameters its <integrator> gave
  std::shared_ptr<ToneOperator> tone_operator;   // the file's <tonemap>, or null
  // What was accepted but is probably not what the author meant, each
  // naming its file and line, and -D names no $name used.
  std::vector<std::string> warnings;

  Scene& operator*() const { return *scene; }
  Scene* operator->() const { return scene.get(); }
};

// Loads a Mitsuba 3 scene file (see DESIGN.md for the subset): reads it into
// nodes, resolves defaults, includes and refs, and instantiates each plugin.
// Every error is a SceneError naming the file and line.
LoadedScene load_scene(const std::filesystem::path& file, const Defines& defines = {});
LoadedScene load_scene_string(std::string_view xml, const std::filesystem::path& file_for_messages,
                              const Defines& defines = {});

// An integrator from a command-line spec, for --integrator: its name,
// optionally followed by parameters as in "bdpt:max_depth=3,mis=balance".
// Values are read as the scene file would read the declared type; errors
// name the spec. Every value in `inherited` (the scene's integrator's) that
// the new integrator declares and the spec does not name is kept, so that
// overriding `path` with `bdpt` keeps the scene's max_depth.
std::shared_ptr<Integrator> make_integrator(const std::string& spec, const GivenValues& inherited = {});

}  // namespace caustica

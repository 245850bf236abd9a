#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "core/scene/scene.h"

namespace caustica {

using Defines = std::map<std::string, std::string>;

// Loads a Mitsuba 3 scene file (see DESIGN.md for the subset): reads it into
// nodes, resolves defaults, includes and refs, and instantiates each plugin.
// Every error is a SceneError naming the file and line.
std::unique_ptr<Scene> load_scene(const std::filesystem::path& file, const Defines& defines = {});
std::unique_ptr<Scene> load_scene_string(std::string_view xml, const std::filesystem::path& file_for_messages,
                                         const Defines& defines = {});

// An integrator from a command-line spec, for --integrator: its name,
// optionally followed by parameters as in "bdpt:max_depth=3,mis=balance".
// Values are read as the scene file would read the declared type; errors
// name the spec.
std::shared_ptr<Integrator> make_integrator(const std::string& spec);

}  // namespace caustica

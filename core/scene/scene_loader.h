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

// An integrator by name with its default parameters, for --integrator.
std::shared_ptr<Integrator> make_default_integrator(const std::string& name);

}  // namespace caustica

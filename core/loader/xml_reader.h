#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/loader/xml_node.h"

namespace caustica {

// How deep elements may nest, and objects refer to objects (<ref>), in a
// scene: far beyond any real scene, well within the stack.
inline constexpr int kMaxSceneDepth = 64;

// Reads `file`, returns its root <scene> node after: includes spliced, defaults
// and $name references resolved (with `defines` from -D taking precedence over
// <default>), and files written for Mitsuba 0.x upgraded. Throws SceneError.
// The names in `defines` that no $name used go to `unused_defines`, and a
// line for each 0.x parameter the upgrade dropped to `upgrade_notes`.
XmlNode read_scene_xml(const std::filesystem::path& file, const std::map<std::string, std::string>& defines = {},
                       std::vector<std::string>* unused_defines = nullptr,
                       std::vector<std::string>* upgrade_notes = nullptr);

// Same, from a string (file name used only for messages and to resolve includes
// relative to its directory).
XmlNode read_scene_xml_string(std::string_view text, const std::filesystem::path& file_for_messages,
                              const std::map<std::string, std::string>& defines = {},
                              std::vector<std::string>* unused_defines = nullptr,
                              std::vector<std::string>* upgrade_notes = nullptr);

// "toWorld" -> "to_world", "intIOR" -> "int_ior": the mechanical part of
// upgrading Mitsuba 0.x parameter names.
std::string camel_to_snake(std::string_view name);

}  // namespace caustica

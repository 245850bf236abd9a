#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace caustica::test {

// Copies scenes/SCENE.xml of the Cornell family (cornell-box by default)
// and the room it includes into a temporary folder named `name`, beside a
// link to the project's meshes, passing each file's text through `edit`;
// returns the copy of SCENE.xml.
std::filesystem::path edited_cornell_box(const std::string& name, const std::function<std::string(std::string)>& edit,
                                         const std::string& scene = "cornell-box");

}  // namespace caustica::test

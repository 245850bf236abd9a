#pragma once

#include <filesystem>
#include <string>

namespace caustica {

// Where one of the engine's data files is (the fitted RGB-to-spectrum table,
// the default OCIO config). An installed binary finds them in
// <prefix>/share/caustica: the executable in <prefix>/bin and the library in
// <prefix>/lib one folder up, the Python module in
// <prefix>/lib/python3/dist-packages three up, wherever the prefix was
// moved. A binary in the build tree finds none there, and uses
// `build_path`, where the build left the file.
std::filesystem::path data_file(const std::string& name, const std::filesystem::path& build_path);

}  // namespace caustica

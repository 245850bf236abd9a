// The strings of the command line that caustica parses itself: the first
// line is an --integrator spec, each further line a -D item, applied to a
// scene that uses two parameters.

#include <cstdint>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "core/loader/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::string spec;
  std::getline(lines, spec);
  std::vector<std::string> items;
  for (std::string line; std::getline(lines, line);) items.push_back(line);
  try {
    caustica::make_integrator(spec);
  } catch (const std::exception&) {
  }
  try {
    caustica::load_scene_string(
        "<scene version='3.0.0'><default name='res' value='8'/><default name='r' value='1'/>"
        "<sensor type='perspective'><film type='hdrfilm'><integer name='width' value='$res'/></film></sensor>"
        "<shape type='sphere'><float name='radius' value='$r'/></shape></scene>",
        "fuzz.xml", caustica::parse_defines(items));
  } catch (const std::exception&) {
  }
  return 0;
}

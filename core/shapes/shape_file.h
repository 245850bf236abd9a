#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "core/files/input_file.h"
#include "core/registry/properties.h"
#include "core/shapes/mesh_format_error.h"

namespace caustica {

// The file a shape's `filename` names, refused as "`what` file '...' not
// found" (or a directory, a device) where it cannot be read.
inline std::filesystem::path shape_file(const Properties& props, const std::string& what) {
  const std::filesystem::path file = props.get_path("filename");
  if (const std::string problem = input_file_problem(file); !problem.empty())
    throw props.error("filename", what + " file '" + file.string() + "' " + problem);
  return file;
}

// What `parse` makes of that file's bytes; its MeshFormatError and a
// failed read name the file.
template <class Parse>
auto read_shape_file(const Properties& props, const std::string& what, const Parse& parse) {
  const std::filesystem::path file = shape_file(props, what);
  // Read in one piece at the file's size: a stream grown by doubling held
  // up to twice the file, and then a copy of it, at the load's peak.
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  std::string bytes(in ? size_t(in.tellg()) : 0, '\0');
  in.seekg(0);
  in.read(bytes.data(), std::streamsize(bytes.size()));
  if (!in) throw props.error("filename", "cannot read " + what + " file '" + file.string() + "'");
  try {
    return parse(bytes);
  } catch (const MeshFormatError& e) {
    throw props.error("filename", what + " file '" + file.string() + "': " + e.what());
  }
}

}  // namespace caustica

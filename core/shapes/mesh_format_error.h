#pragma once

#include <stdexcept>

namespace caustica {

// A mesh file the project's own readers cannot read (PlyError,
// SerializedError); what() says where in the file and why.
class MeshFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace caustica

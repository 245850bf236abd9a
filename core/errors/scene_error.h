#pragma once

#include <stdexcept>
#include <string>

namespace caustica {

struct SourceLocation {
  std::string file;
  int line = 0;

  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

// An error in a scene description; what() reads "FILE:LINE: problem".
class SceneError : public std::runtime_error {
 public:
  SceneError(const SourceLocation& where, const std::string& problem)
      : std::runtime_error(where.str() + ": " + problem), where_(where) {}
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

}  // namespace caustica

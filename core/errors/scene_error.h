#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace caustica {

struct SourceLocation {
  std::string file;
  int line = 0;

  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

// `problem` with every quoted ('...') passage longer than a line cut to its
// start, and the whole bounded: a scene file's hostile 10 MB value must not
// come back whole in a message.
std::string shorten_quoted(std::string_view problem);

// An error in a scene description; what() reads "FILE:LINE: problem".
class SceneError : public std::runtime_error {
 public:
  SceneError(const SourceLocation& where, const std::string& problem)
      : std::runtime_error(where.str() + ": " + shorten_quoted(problem)), where_(where) {}
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

}  // namespace caustica

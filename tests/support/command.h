#pragma once

#include <string>

namespace caustica::test {

struct CommandResult {
  int status;
  std::string output;  // stdout and stderr together
};

// Runs the caustica executable with `args` (shell syntax) and collects what it prints.
CommandResult run_caustica(const std::string& args);

}  // namespace caustica::test

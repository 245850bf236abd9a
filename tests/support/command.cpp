#include "tests/support/command.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace caustica::test {

CommandResult run_caustica(const std::string& args) {
  const std::string cmd = std::string(CAUSTICA_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

}  // namespace caustica::test

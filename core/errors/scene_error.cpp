#include "core/errors/scene_error.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr size_t kMaxQuoted = 80;
constexpr size_t kMaxProblem = 2000;

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::string shorten_quoted(std::string_view problem) {
  std::string out;
  size_t i = 0;
  while (i < problem.size()) {
    const size_t open = problem.find('\'', i);
    const size_t close = open == std::string_view::npos ? open : problem.find('\'', open + 1);
    if (close == std::string_view::npos) {
      out += problem.substr(i);
      break;
    }
    const std::string_view quoted = problem.substr(open + 1, close - open - 1);
    out += problem.substr(i, open + 1 - i);
    if (quoted.size() <= kMaxQuoted) {
      out += quoted;
    } else {
      out += quoted.substr(0, kMaxQuoted - 20);
      out += "... (" + std::to_string(quoted.size()) + " characters)";
    }
    out += '\'';
    i = close + 1;
  }
  if (out.size() > kMaxProblem) out = out.substr(0, kMaxProblem) + "... (message cut)";
  return out;
}

}  // namespace caustica

#pragma once

#include <string>

namespace caustica::test {

// What the Error that `run` throws says, or "no error" when it returns.
template <class Error, class Run>
std::string thrown_message(const Run& run) {
  try {
    run();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace caustica::test

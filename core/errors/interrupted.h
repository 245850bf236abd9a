#pragma once

#include <atomic>
#include <stdexcept>

namespace caustica {

// The process's request to stop: set by the command line's SIGINT and
// SIGTERM handlers, polled by work that is long but not a render pass
// (mesh loads), which then throws Interrupted.
std::atomic<bool>& stop_request();

class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace caustica

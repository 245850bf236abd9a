#include "core/errors/interrupted.h"

namespace caustica {

std::atomic<bool>& stop_request() {
  static std::atomic<bool> requested{false};
  static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");
  return requested;
}

}  // namespace caustica

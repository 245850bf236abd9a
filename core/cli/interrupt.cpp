#include "core/cli/interrupt.h"

#include <csignal>

namespace caustica {

namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

void on_interrupt(int) {
  requested.store(true);
  std::signal(SIGINT, SIG_DFL);
}

}  // namespace

void install_interrupt_handler() { std::signal(SIGINT, on_interrupt); }

const std::atomic<bool>& interrupt_requested() { return requested; }

}  // namespace caustica

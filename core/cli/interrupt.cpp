#include "core/cli/interrupt.h"

#include <csignal>

#include "core/errors/interrupted.h"

namespace caustica {

namespace {

void on_interrupt(int signal) {
  stop_request().store(true);
  std::signal(signal, SIG_DFL);
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

const std::atomic<bool>& interrupt_requested() { return stop_request(); }

}  // namespace caustica

#include "core/cli/interrupt.h"

#include <csignal>

#include "core/errors/interrupted.h"
#include "core/image/atomic_file.h"

namespace caustica {

namespace {

// The second signal ends the process as the signal would by default, but
// not before removing the temporary file of an output being written.
void on_interrupt(int signal) {
  if (!stop_request().exchange(true)) return;
  remove_pending_temporary_file();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

const std::atomic<bool>& interrupt_requested() { return stop_request(); }

}  // namespace caustica

#pragma once

#include <atomic>

namespace caustica {

// Ctrl-C (SIGINT) handling for long renders: the first interrupt asks the
// render to stop at the next pass boundary so the image so far is written;
// a second one ends the program at once.
void install_interrupt_handler();
const std::atomic<bool>& interrupt_requested();

}  // namespace caustica

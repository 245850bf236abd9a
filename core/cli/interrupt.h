#pragma once

#include <atomic>

namespace caustica {

// SIGINT (Ctrl-C) and SIGTERM (what `timeout` and cluster schedulers send)
// handling for long renders: the first one asks the render to stop at the
// next pass boundary so the image so far is written (a mesh load stops at
// once, as nothing is finished yet); a second one ends the program at once.
void install_interrupt_handler();
const std::atomic<bool>& interrupt_requested();

}  // namespace caustica

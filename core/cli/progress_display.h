#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "core/render/renderer.h"

namespace caustica {

// Shows a render's progress on stderr from a thread of its own: a bar with
// percentage, elapsed time, ETA and Mrays/s redrawn in place on a terminal,
// a plain line every few seconds otherwise. Stops when destroyed.
class ProgressDisplay {
 public:
  ProgressDisplay(const RenderProgress& progress, double time_limit);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

 private:
  void run();
  void print(bool final) const;

  const RenderProgress& progress_;
  double time_limit_;
  bool tty_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace caustica

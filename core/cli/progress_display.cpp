#include "core/cli/progress_display.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace caustica {

namespace {

std::string format_seconds(double s) {
  const int total = int(s + 0.5);
  char buf[32];
  if (total >= 3600)
    std::snprintf(buf, sizeof buf, "%d:%02d:%02d", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(buf, sizeof buf, "%d:%02d", total / 60, total % 60);
  return buf;
}

}  // namespace

ProgressDisplay::ProgressDisplay(const RenderProgress& progress, double time_limit)
    : progress_(progress),
      time_limit_(time_limit),
      tty_(isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      thread_([this] { run(); }) {}

ProgressDisplay::~ProgressDisplay() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_one();
  thread_.join();
  print(true);
}

void ProgressDisplay::run() {
  const auto period = tty_ ? std::chrono::milliseconds(250) : std::chrono::milliseconds(10000);
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return done_; })) print(false);
}

void ProgressDisplay::print(bool final) const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double done = double(progress_.pixel_samples.load());
  const double target = double(progress_.pixel_samples_target.load());
  double fraction = target > 0 ? done / target : (time_limit_ > 0 ? elapsed / time_limit_ : 0);
  fraction = std::clamp(fraction, 0.0, 1.0);
  const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  const double mrays = elapsed > 0 ? progress_.rays.load() / elapsed * 1e-6 : 0;
  char stats[96];
  std::snprintf(stats, sizeof stats, "%5.1f%%  %s elapsed, %s left, %.1f Mrays/s", 100 * fraction,
                format_seconds(elapsed).c_str(), format_seconds(eta).c_str(), mrays);
  if (!tty_) {
    std::fprintf(stderr, "rendering: %s\n", stats);
    return;
  }
  constexpr int kWidth = 30;
  const int filled = int(fraction * kWidth);
  char bar[kWidth + 3] = {};
  bar[0] = '[';
  for (int i = 0; i < kWidth; ++i) bar[i + 1] = i < filled ? '#' : '.';
  bar[kWidth + 1] = ']';
  std::fprintf(stderr, "\r%s %s\033[K%s", bar, stats, final ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace caustica

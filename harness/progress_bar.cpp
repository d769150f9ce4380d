#include "harness/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include <fmt/core.h>

namespace prism::harness {

std::string timeLeftText(std::size_t done, std::size_t total, double seconds) {
  if (done == 0 || done >= total || !(seconds >= 1.0)) return {};
  const double left = std::max(1.0, seconds * static_cast<double>(total - done) / static_cast<double>(done));
  if (left < 99.5) return fmt::format("about {:.0f} s left", left);
  if (left < 99.5 * 60.0) return fmt::format("about {:.0f} min left", left / 60.0);
  return fmt::format("about {:.1f} h left", left / 3600.0);
}

ProgressBar::ProgressBar(std::string label)
    : mLabel(std::move(label)), mTerminal(isatty(fileno(stderr)) != 0), mStart(std::chrono::steady_clock::now()) {}

void ProgressBar::update(std::size_t done, std::size_t total) {
  int percent = total ? static_cast<int>(100 * done / total) : 100;
  if (!mTerminal) percent -= percent % 25;  // a line at 0, 25, 50, 75 and 100 %
  if (percent == mLastPercent) return;
  mLastPercent = percent;
  constexpr int kWidth = 40;
  int filled = percent * kWidth / 100;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
  const std::string left = timeLeftText(done, total, seconds);
  // On a terminal the line is redrawn in place: cleared to its end, as the estimate may shorten.
  fmt::print(stderr, "{}{} [{}{}] {:3}% {:.1f} s{}{}", mTerminal ? "\r" : "", mLabel,
             std::string(static_cast<std::size_t>(filled), '#'), std::string(static_cast<std::size_t>(kWidth - filled), '.'),
             percent, seconds, left.empty() ? "" : ", " + left, mTerminal ? "\033[K" : "");
  if (done >= total || !mTerminal) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace prism::harness

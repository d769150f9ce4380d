#include "harness/progress_bar.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/core.h>

namespace prism::harness {

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
  fmt::print(stderr, "{}{} [{}{}] {:3}% {:.1f} s", mTerminal ? "\r" : "", mLabel,
             std::string(static_cast<std::size_t>(filled), '#'), std::string(static_cast<std::size_t>(kWidth - filled), '.'),
             percent, seconds);
  if (done >= total || !mTerminal) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace prism::harness

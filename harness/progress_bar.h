// A progress bar on stderr for long work (table optimisation, precomputation, references):
// redrawn in place at most once per percent with the elapsed time and an estimate of the time
// left, finished with a newline. Where stderr is no terminal (a log, CI), a line at each quarter
// instead, since a log keeps every redraw (2.4 kB of them for a one-second fit).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace prism::harness {

// The time left for `done` of `total` units after `seconds`, at the rate so far: "about 40 s
// left", "about 12 min left", "about 2.5 h left"; empty when nothing or everything is done, or
// before a second has passed (too little to extrapolate from).
std::string timeLeftText(std::size_t done, std::size_t total, double seconds);

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  void update(std::size_t done, std::size_t total);

 private:
  std::string mLabel;
  bool mTerminal;
  int mLastPercent = -1;
  std::chrono::steady_clock::time_point mStart;
};

}  // namespace prism::harness

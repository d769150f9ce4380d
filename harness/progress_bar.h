// A progress bar on stderr for long work (table optimisation, precomputation, references):
// redrawn in place at most once per percent, finished with a newline and the elapsed time. Where
// stderr is no terminal (a log, CI), a line at each quarter instead, since a log keeps every
// redraw (2.4 kB of them for a one-second fit).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace prism::harness {

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

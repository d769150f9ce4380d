// One task's share of work split into N tasks (a Slurm array's element I of N): the option texts
// "I/N" and "A:B", the share of a count that task I takes, and the check that parts cover a count. Every split of Prism's batch work
// (a render's rows, a sweep's experiments, a table's columns) uses these, so that task I of N
// takes the same share wherever it is computed: in prism, and in the shell of a job script.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace prism {

// The most tasks a piece of work is split into.
inline constexpr int kMaxTasks = 1'000'000;

struct TaskIndex {
  int index = 0;  // 0 ≤ index < count
  int count = 1;
};

// "I/N" with 0 ≤ I < N ≤ 1 000 000; Error naming `option` otherwise.
TaskIndex parseTaskIndex(std::string_view text, std::string_view option);

// A half-open range [begin, end) of indices.
struct IndexRange {
  int begin = 0;
  int end = 0;
  int size() const { return end - begin; }
  bool operator==(const IndexRange&) const = default;
};

// "A:B" with 0 ≤ A < B (B ≤ 2³¹ − 1); Error naming `option` otherwise.
IndexRange parseIndexRange(std::string_view text, std::string_view option);

// That `ranges` (names[i] saying whose ranges[i] is, e.g. a part's file) hold every index of
// [0, total) exactly once, as the parts of a split piece of work must before `prism merge` puts
// them together. Error "merge: NOUN A:B are missing" for the first gap, "merge: NOUN A:B are in
// both NAME and NAME" for the first overlap.
void checkCoveredOnce(const std::vector<IndexRange>& ranges, const std::vector<std::string>& names, int total,
                      std::string_view noun);

// Task I's share of `total` items: [⌊I·total/N⌋, ⌊(I+1)·total/N⌋). The shares of I = 0 … N − 1
// tile [0, total) and differ in size by at most one; none is empty when N ≤ total.
IndexRange shareOf(TaskIndex task, int total);

}  // namespace prism

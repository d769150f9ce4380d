#include "core/task_split.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <numeric>
#include <string>

#include "core/error.h"

namespace prism {
namespace {

// A whole number that is the whole of `text`, within [0, max]; false otherwise.
bool parseWhole(std::string_view text, long long max, int& value) {
  long long v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v < 0 || v > max) return false;
  value = static_cast<int>(v);
  return true;
}

}  // namespace

TaskIndex parseTaskIndex(std::string_view text, std::string_view option) {
  const std::size_t slash = text.find('/');
  TaskIndex task;
  if (slash == std::string_view::npos || !parseWhole(text.substr(0, slash), kMaxTasks - 1, task.index) ||
      !parseWhole(text.substr(slash + 1), kMaxTasks, task.count) || task.count < 1 || task.index >= task.count) {
    throw Error(std::string(option) + ": expected I/N with 0 ≤ I < N (task I of N), got \"" + excerpt(text) + "\"");
  }
  return task;
}

IndexRange parseIndexRange(std::string_view text, std::string_view option) {
  const std::size_t colon = text.find(':');
  IndexRange range;
  if (colon == std::string_view::npos || !parseWhole(text.substr(0, colon), INT32_MAX, range.begin) ||
      !parseWhole(text.substr(colon + 1), INT32_MAX, range.end) || range.begin >= range.end) {
    throw Error(std::string(option) + ": expected A:B with 0 ≤ A < B, got \"" + excerpt(text) + "\"");
  }
  return range;
}

IndexRange shareOf(TaskIndex task, int total) {
  PRISM_CHECK(task.count >= 1 && task.index >= 0 && task.index < task.count && total >= 0);
  auto bound = [&](long long i) { return static_cast<int>(i * total / task.count); };
  return {bound(task.index), bound(task.index + 1LL)};
}

void checkCoveredOnce(const std::vector<IndexRange>& ranges, const std::vector<std::string>& names, int total,
                      std::string_view noun) {
  PRISM_CHECK(ranges.size() == names.size());
  std::vector<std::size_t> order(ranges.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(ranges[a].begin, ranges[a].end) < std::pair(ranges[b].begin, ranges[b].end);
  });
  auto span = [&](int a, int b) { return "merge: " + std::string(noun) + " " + std::to_string(a) + ":" + std::to_string(b); };
  int covered = 0;
  std::size_t last = 0;
  for (std::size_t i : order) {
    const IndexRange r = ranges[i];
    if (r.begin > covered) throw Error(span(covered, r.begin) + " are missing");
    if (r.begin < covered)
      throw Error(span(r.begin, std::min(covered, r.end)) + " are in both " + names[last] + " and " + names[i]);
    covered = r.end;
    last = i;
  }
  if (covered < total) throw Error(span(covered, total) + " are missing");
}

}  // namespace prism

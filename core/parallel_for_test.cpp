#include "core/parallel_for.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace prism {
namespace {

std::set<std::thread::id> threadsOf(std::size_t items, unsigned threads) {
  std::set<std::thread::id> ids;
  std::mutex mutex;
  parallelFor(items, threads, [&](std::size_t) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));  // long enough for every worker to start
    std::lock_guard lock(mutex);
    ids.insert(std::this_thread::get_id());
  });
  return ids;
}

// prism validate --threads N (a Slurm task's share of a node) caps what "all threads" means for
// every pass at once; an explicit count is still taken as given.
TEST(ParallelFor, AllThreadsFollowsTheProcessCap) {
  setAllThreads(1);  // below any machine's count, so that the test can fail on 2 cores too
  EXPECT_EQ(allThreads(), 1u);
  EXPECT_EQ(threadsOf(400, 0).size(), 1u);
  EXPECT_GT(threadsOf(400, 3).size(), 1u);
  setAllThreads(0);
  EXPECT_EQ(allThreads(), std::max(1u, std::thread::hardware_concurrency()));
}

TEST(ParallelFor, EveryItemRunsOnce) {
  std::vector<int> hits(1000, 0);
  parallelFor(hits.size(), 4, [&](std::size_t i) { ++hits[i]; });
  for (int h : hits) EXPECT_EQ(h, 1);
}

}  // namespace
}  // namespace prism

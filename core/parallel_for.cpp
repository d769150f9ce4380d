#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

namespace prism {
namespace {
std::atomic<unsigned> gAllThreads{0};
}  // namespace

unsigned allThreads() {
  const unsigned cap = gAllThreads.load();
  return cap != 0 ? cap : std::max(1u, std::thread::hardware_concurrency());
}

void setAllThreads(unsigned threads) { gAllThreads.store(threads); }

void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                 const std::function<void(std::size_t, std::size_t)>& progress) {
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progressMutex;
  auto worker = [&] {
    for (std::size_t item = next++; item < count; item = next++) {
      body(item);
      if (progress) {
        std::lock_guard lock(progressMutex);
        progress(++done, count);
      }
    }
  };
  if (threads == 0) threads = allThreads();
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < threads && t < count; ++t) pool.emplace_back(worker);
  worker();
}

}  // namespace prism

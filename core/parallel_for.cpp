#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

namespace prism {

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
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < threads && t < count; ++t) pool.emplace_back(worker);
  worker();
}

}  // namespace prism

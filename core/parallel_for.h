// Shares independent work items out to threads, in the order of an atomic counter. Each item
// must write only its own outputs, so results do not depend on the thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace prism {

// The most threads a command's --threads may ask for: beyond the largest machines' cores, where
// 100 000 threads ran a bake 150 times slower than the machine's own count.
inline constexpr unsigned kMaxThreads = 4096;

// What "threads = 0" means in this process: every hardware thread, unless a command that takes
// --threads but runs many passes (validate: path tracer, PRT bakes, nebula references, tables)
// capped it with setAllThreads(n) (0 lifts the cap).
unsigned allThreads();
void setAllThreads(unsigned threads);

// threads = 0: allThreads(). progress, if set, is called serialised after each item
// with (items done, items in all).
void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t item)>& body,
                 const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace prism

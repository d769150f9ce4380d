// The script's `soak FRAMES [MB]`: the viewer run for many frames while its settings change, to
// find what a frame leaks. Parameter changes every 10 frames, a resize every 100, the split
// toggled every 250; GL objects and memory counted in the same state before and after, printed,
// and Error when any kind of GL object is not back to its count, or when the heap in use or the
// anonymous resident memory (allocator trimmed) grew by more than maxGrowthMb (when given).
#pragma once

#include <optional>

#include "viewer/viewer_loop.h"

namespace prism::viewer {

void soak(Viewer& viewer, int frames, std::optional<double> maxGrowthMb);

}  // namespace prism::viewer

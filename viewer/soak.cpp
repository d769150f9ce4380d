#include "viewer/soak.h"

#include <malloc.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "gpu/object_counter.h"
#include "core/error.h"

namespace prism::viewer {
namespace {

// The process's memory in MB once the allocator has given its free pages back (malloc_trim).
// Untrimmed, resident memory also counts the freed memory glibc keeps for reuse (47 MB after a
// 1 000-frame soak round), which varies from run to run, leak or not.
struct MemoryUse {
  double heap = 0.0;       // handed out by malloc and not freed, over every arena (mallinfo2)
  double anonymous = 0.0;  // resident anonymous pages: the heap, thread stacks, compiled shaders
  double files = 0.0;      // resident pages of mapped files: the code of the libraries run so far
};

MemoryUse memoryUse() {
  malloc_trim(0);
  MemoryUse m;
  struct mallinfo2 info = mallinfo2();
  m.heap = static_cast<double>(info.uordblks + info.hblkhd) / (1024.0 * 1024.0);
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    std::istringstream words(line);
    std::string key;
    double kilobytes = 0.0;
    words >> key >> kilobytes;
    if (key == "RssAnon:") m.anonymous = kilobytes / 1024.0;
    if (key == "RssFile:") m.files = kilobytes / 1024.0;
  }
  return m;
}

}  // namespace

void soak(Viewer& viewer, int frames, std::optional<double> maxGrowthMb) {
  ViewSettings& view = viewer.view();
  std::vector<Light>& lights = viewer.scene().lights;
  Changes& changes = viewer.changes();
  const ViewSettings start = view;
  const float startIntensity = lights.empty() ? 0.0f : lights[0].intensity;
  const gpu::WindowSize startSize = viewer.window().framebufferSize();
  // Both views made before the first count, so that the counts compare like with like.
  view.split = true;
  changes.settings = true;
  viewer.frame();
  view = start;
  changes.settings = true;
  for (int i = 0; i < 20; ++i) viewer.frame();
  gpu::GlObjectCounts objectsBefore = gpu::liveGlObjects();
  const MemoryUse memoryBefore = memoryUse();
  const render::RenderMode modes[] = {render::RenderMode::JakobHanika, render::RenderMode::Rgb,
                                      render::RenderMode::Naive};
  const int counts[] = {4, 8, 16, 12};
  const SamplingStrategy strategies[] = {SamplingStrategy::Uniform, SamplingStrategy::Rotated,
                                         SamplingStrategy::Stratified, SamplingStrategy::Lights};
  for (int i = 1; i <= frames; ++i) {
    if (i % 10 == 0) {
      int k = i / 10;
      view.left.mode = modes[k % 3];
      view.left.sampling.count = counts[k % 4];
      view.left.sampling.strategy = strategies[k % 4];
      view.left.gbufferAlbedo = k % 7 == 0 ? render::GBufferAlbedo::Coefficients : render::GBufferAlbedo::Rgb;
      if (!lights.empty()) {
        lights[0].intensity *= k % 2 ? 1.25f : 0.8f;
        changes.scene = true;
      }
      changes.settings = true;
    }
    if (i % 100 == 0) {
      bool smaller = (i / 100) % 2;
      viewer.resize(smaller ? startSize.width * 3 / 4 : startSize.width,
                    smaller ? startSize.height * 3 / 4 : startSize.height);
    }
    if (i % 250 == 0) {
      view.split = !view.split;
      view.heatMap = view.split;
      changes.settings = true;
    }
    viewer.frame();
  }
  view = start;
  if (!lights.empty()) lights[0].intensity = startIntensity;
  changes.settings = changes.scene = true;
  viewer.resize(startSize.width, startSize.height);
  for (int i = 0; i < 20; ++i) viewer.frame();
  gpu::GlObjectCounts objectsAfter = gpu::liveGlObjects();
  const MemoryUse memoryAfter = memoryUse();
  fmt::print("soak: {} frames with setting changes every 10, resizes every 100, split toggled every 250\n", frames);
  fmt::print("soak: GL objects {} -> {} ({} -> {})\n", objectsBefore.total(), objectsAfter.total(),
             gpu::describeGlObjects(objectsBefore), gpu::describeGlObjects(objectsAfter));
  fmt::print("soak: heap in use {:.1f} MB -> {:.1f} MB; resident, allocator trimmed: anonymous {:.1f} MB -> "
             "{:.1f} MB, mapped files {:.1f} MB -> {:.1f} MB\n",
             memoryBefore.heap, memoryAfter.heap, memoryBefore.anonymous, memoryAfter.anonymous, memoryBefore.files,
             memoryAfter.files);
  std::fflush(stdout);
  if (!(objectsAfter == objectsBefore)) throw Error("soak: GL objects were left behind (or lost)");
  if (!maxGrowthMb) return;
  if (!(memoryAfter.heap - memoryBefore.heap <= *maxGrowthMb)) {
    throw Error(fmt::format("soak: the heap in use grew by {:.1f} MB (bound {:g} MB)",
                            memoryAfter.heap - memoryBefore.heap, *maxGrowthMb));
  }
  if (!(memoryAfter.anonymous - memoryBefore.anonymous <= *maxGrowthMb)) {
    throw Error(fmt::format("soak: anonymous resident memory grew by {:.1f} MB (bound {:g} MB)",
                            memoryAfter.anonymous - memoryBefore.anonymous, *maxGrowthMb));
  }
}

}  // namespace prism::viewer

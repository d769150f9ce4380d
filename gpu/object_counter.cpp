#include "gpu/object_counter.h"

#include <atomic>

namespace prism::gpu {
namespace {

// Relaxed: the counts order nothing; GL calls on one context are on one thread anyway.
std::array<std::atomic<std::int64_t>, kGlObjectKinds> gLive{};

}  // namespace

std::string_view glObjectKindName(GlObjectKind kind) {
  switch (kind) {
    case GlObjectKind::Buffer: return "buffers";
    case GlObjectKind::Texture: return "textures";
    case GlObjectKind::Framebuffer: return "framebuffers";
    case GlObjectKind::VertexArray: return "vertex arrays";
    case GlObjectKind::Program: return "programs";
    case GlObjectKind::Query: return "queries";
  }
  return "unknown";
}

std::int64_t GlObjectCounts::total() const {
  std::int64_t sum = 0;
  for (std::int64_t n : live) sum += n;
  return sum;
}

GlObjectCounts liveGlObjects() {
  GlObjectCounts counts;
  for (std::size_t i = 0; i < kGlObjectKinds; ++i)
    counts.live[i] = gLive[i].load(std::memory_order_relaxed);
  return counts;
}

std::string describeGlObjects(const GlObjectCounts& counts) {
  std::string text;
  for (std::size_t i = 0; i < kGlObjectKinds; ++i) {
    if (i) text += ", ";
    text += glObjectKindName(static_cast<GlObjectKind>(i));
    text += ' ';
    text += std::to_string(counts.live[i]);
  }
  return text;
}

void countGlObjects(GlObjectKind kind, std::int64_t delta) {
  gLive[static_cast<std::size_t>(kind)].fetch_add(delta, std::memory_order_relaxed);
}

}  // namespace prism::gpu

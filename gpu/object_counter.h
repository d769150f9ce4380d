// How many GL objects the wrappers of this layer have created and not yet deleted, per kind,
// process-wide (over all contexts). Each wrapper counts its names when it creates them and
// uncounts them when it deletes them (destructor or move-assignment); moves transfer a name
// without counting. The viewer asserts on shutdown that the counts are back where they started,
// and tests do the same around a block: a leaked GL name is otherwise invisible, since a
// context's objects die with it. Names created with raw GL calls are not counted.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace prism::gpu {

enum class GlObjectKind { Buffer, Texture, Framebuffer, VertexArray, Program, Query };
inline constexpr std::size_t kGlObjectKinds = 6;

// "buffers", "textures", ... for messages.
std::string_view glObjectKindName(GlObjectKind kind);

struct GlObjectCounts {
  std::array<std::int64_t, kGlObjectKinds> live{};

  std::int64_t operator[](GlObjectKind kind) const { return live[static_cast<std::size_t>(kind)]; }
  std::int64_t total() const;
  bool operator==(const GlObjectCounts&) const = default;
};

// A snapshot of the live counts.
GlObjectCounts liveGlObjects();

// "buffers 2, textures 1, framebuffers 0, vertex arrays 0, programs 1, queries 0".
std::string describeGlObjects(const GlObjectCounts& counts);

// For the wrappers: `delta` names of `kind` were created (> 0) or deleted (< 0).
void countGlObjects(GlObjectKind kind, std::int64_t delta);

}  // namespace prism::gpu

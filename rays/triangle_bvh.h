// Triangle meshes in an Embree 3 BVH (Debian's libembree-dev): closest hits and occlusion, for
// every part of Prism that traces rays on the CPU — the reference path tracer (a scene, one
// geometry per mesh) and PRT's transfer bake (an object against itself). Embree's failures
// become prism::Error naming what failed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include <glm/glm.hpp>

namespace prism::rays {

// One mesh to trace: its positions and its triangles (three indices each, < positions.size(),
// PRISM_CHECKed: the loaders refuse such meshes first), under an id that hits report; ids are
// distinct but need not be dense. Read at construction only (copied).
struct TriangleMesh {
  std::uint32_t id = 0;
  std::span<const glm::vec3> positions;
  std::span<const std::uint32_t> indices;
};

struct TriangleHit {
  float distance = 0.0f;       // along the (unit) direction
  std::uint32_t geometry = 0;  // the TriangleMesh's id
  std::uint32_t triangle = 0;  // within that mesh
  float u = 0.0f, v = 0.0f;    // barycentrics: p = (1 − u − v)·p0 + u·p1 + v·p2
};

class TriangleBvh {
 public:
  // Meshes without indices are left out. Error when Embree cannot create its device, allocate
  // the buffers or build the BVH (high quality: built once, traced many times).
  explicit TriangleBvh(std::span<const TriangleMesh> meshes);
  ~TriangleBvh();
  TriangleBvh(TriangleBvh&&) noexcept;
  TriangleBvh& operator=(TriangleBvh&&) noexcept;

  // Thread-safe. `direction` must be unit; hits closer than tMin or farther than tMax are ignored.
  std::optional<TriangleHit> intersect(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                       float tMax) const;
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) const;

 private:
  struct Handles;
  std::unique_ptr<Handles> mHandles;
};

}  // namespace prism::rays

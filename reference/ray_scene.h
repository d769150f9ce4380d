// A scene's triangles in an Embree 3 BVH (Debian's libembree-dev), for the reference path
// tracer: closest hits and shadow rays. One Embree geometry per Scene mesh, so a hit's geometry
// id is the mesh index and its primitive id the triangle within it.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::reference {

struct RayHit {
  float distance = 0.0f;    // along the (unit) direction
  std::uint32_t mesh = 0;   // index into Scene::meshes
  std::uint32_t triangle = 0;
  float u = 0.0f, v = 0.0f;  // barycentrics: p = (1 − u − v)·p0 + u·p1 + v·p2
};

class RayScene {
 public:
  // The scene must outlive this (vertex data is copied into Embree's buffers, names are not).
  // Error naming Embree's message when the device or the BVH cannot be built.
  explicit RayScene(const Scene& scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Thread-safe. `direction` must be unit; hits closer than tMin or farther than tMax are ignored.
  std::optional<RayHit> intersect(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                  float tMax) const;
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) const;

 private:
  struct Handles;
  Handles* mHandles;
};

}  // namespace prism::reference

// A scene's triangles in a BVH (prism::rays), for the reference path tracer's closest hits and
// shadow rays: one geometry per Scene mesh, so a hit's geometry is the mesh index and its triangle
// the triangle within it.
#pragma once

#include "rays/triangle_bvh.h"
#include "scene/scene.h"

namespace prism::reference {

// Error naming Embree's message when the BVH cannot be built.
rays::TriangleBvh sceneRays(const Scene& scene);

}  // namespace prism::reference

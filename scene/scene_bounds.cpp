#include <limits>

#include "scene/scene.h"

namespace prism {

Bounds sceneBounds(const Scene& scene) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  Bounds b{glm::vec3(kInf), glm::vec3(-kInf)};
  bool any = false;
  for (const Mesh& mesh : scene.meshes) {
    for (const Vertex& v : mesh.vertices) {
      b.min = glm::min(b.min, v.position);
      b.max = glm::max(b.max, v.position);
      any = true;
    }
  }
  return any ? b : Bounds{};
}

}  // namespace prism

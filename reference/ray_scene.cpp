#include "reference/ray_scene.h"

#include <vector>

namespace prism::reference {

rays::TriangleBvh sceneRays(const Scene& scene) {
  std::vector<std::vector<glm::vec3>> positions(scene.meshes.size());
  std::vector<rays::TriangleMesh> meshes;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    positions[m].reserve(mesh.vertices.size());
    for (const Vertex& vertex : mesh.vertices) positions[m].push_back(vertex.position);
    meshes.push_back({static_cast<std::uint32_t>(m), positions[m], mesh.indices});
  }
  return rays::TriangleBvh(meshes);
}

}  // namespace prism::reference

#include "techniques/prt/gpu/prt_scene_mesh.h"

#include <algorithm>

#include "core/error.h"
#include "techniques/prt/prt_section.h"

namespace prism::prt {
namespace {

// Scenes are y-up (glTF's convention); PRT's environments have their zenith at +z.
glm::vec3 zUp(const glm::vec3& p) { return {p.x, -p.z, p.y}; }

}  // namespace

PrtSceneMesh prtSceneMesh(const Scene& scene, PrtMeshes which) {
  const bool anyPrt = std::ranges::any_of(scene.meshes, [](const Mesh& m) { return m.technique == PrtSection::kKey; });
  const bool all = which == PrtMeshes::PrtObjectsElseAll && !anyPrt;
  PrtSceneMesh out;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& m = scene.meshes[i];
    if (!all && m.technique != PrtSection::kKey) continue;
    out.meshes.push_back(i);
    const auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
    for (const Vertex& v : m.vertices) {
      out.mesh.positions.push_back(zUp(v.position));
      float length = glm::length(v.normal);
      out.mesh.normals.push_back(length > 0.0f ? zUp(v.normal / length) : glm::vec3(0.0f, 0.0f, 1.0f));
      out.vertexMaterial.push_back(std::max(m.material, 0));
    }
    for (std::uint32_t index : m.indices) out.mesh.indices.push_back(base + index);
  }
  return out;
}

BakeSettings sceneBakeSettings(const Scene& scene) {
  const PrtSection* section = scene.techniques.find<PrtSection>();
  if (!section) throw Error("the scene has no \"prt\" section");
  return {section->samples, section->shadows};
}

}  // namespace prism::prt

// What of a scene PRT bakes: its PRT objects' meshes (every mesh when it marks none, for `prism prt
// bake` of a plain scene or model) as one occluder set, in world space turned from the scenes' y-up
// to PRT's z-up. The renderer's PRT pass, `prism prt bake` and the commands that bake ahead of a
// renderer all take it from here, so that they share one transfer cache entry. No OpenGL: it lives
// beside the pass because it reads a Scene, which the CPU half of PRT sits below.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "techniques/prt/transfer_bake.h"

namespace prism::prt {

struct PrtSceneMesh {
  PrtMesh mesh;
  std::vector<std::size_t> meshes;  // indices into Scene::meshes, in the order gathered
  std::vector<int> vertexMaterial;  // Scene::materials index of each vertex (0 for none)
};

enum class PrtMeshes { PrtObjects, PrtObjectsElseAll };

PrtSceneMesh prtSceneMesh(const Scene& scene, PrtMeshes which);

// The scene's bake settings: its "prt" section's samples and shadowing. Error when it has none.
BakeSettings sceneBakeSettings(const Scene& scene);

}  // namespace prism::prt

#include "reference/ray_scene.h"

#include <gtest/gtest.h>

#include "scene/procedural_mesh.h"

namespace prism::reference {
namespace {

TEST(SceneRays, AHitsGeometryIsItsMeshIndexEvenPastAnEmptyMesh) {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 1.0f, 128));
  scene.meshes.push_back(Mesh{});
  scene.meshes.push_back(makePlane({0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {10.0f, 10.0f}));
  rays::TriangleBvh rays = sceneRays(scene);

  auto sphere = rays.intersect({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f);
  ASSERT_TRUE(sphere);
  EXPECT_EQ(sphere->geometry, 0u);
  EXPECT_NEAR(sphere->distance, 4.0f, 1e-3f);  // the tessellated sphere's pole-facing facets

  auto floor = rays.intersect({3.0f, 5.0f, 3.0f}, {0.0f, -1.0f, 0.0f}, 0.0f, 1e30f);
  ASSERT_TRUE(floor);
  EXPECT_EQ(floor->geometry, 2u);
  EXPECT_NEAR(floor->distance, 6.0f, 1e-5f);
  EXPECT_LT(floor->triangle, scene.meshes[2].indices.size() / 3);
}

TEST(SceneRays, AnEmptySceneHasNothingToHit) {
  rays::TriangleBvh rays = sceneRays(Scene{});
  EXPECT_FALSE(rays.intersect({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
  EXPECT_FALSE(rays.occluded({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
}

}  // namespace
}  // namespace prism::reference

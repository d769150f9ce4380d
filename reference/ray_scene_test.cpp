#include "reference/ray_scene.h"

#include <gtest/gtest.h>

#include "scene/procedural_mesh.h"

namespace prism::reference {
namespace {

Scene twoMeshes() {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 1.0f, 128));
  scene.meshes.push_back(makePlane({0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {10.0f, 10.0f}));
  return scene;
}

TEST(RayScene, ClosestHitNamesTheMeshAndItsDistance) {
  Scene scene = twoMeshes();
  RayScene rays(scene);
  auto hit = rays.intersect({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->mesh, 0u);
  EXPECT_NEAR(hit->distance, 4.0f, 1e-3f);  // the tessellated sphere's pole-facing facets

  auto floor = rays.intersect({3.0f, 5.0f, 3.0f}, {0.0f, -1.0f, 0.0f}, 0.0f, 1e30f);
  ASSERT_TRUE(floor);
  EXPECT_EQ(floor->mesh, 1u);
  EXPECT_NEAR(floor->distance, 6.0f, 1e-5f);
}

TEST(RayScene, RespectsTheRayIntervalAndMissesWhatIsNotThere) {
  Scene scene = twoMeshes();
  RayScene rays(scene);
  EXPECT_FALSE(rays.intersect({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, 1e30f));
  EXPECT_FALSE(rays.intersect({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 3.9f));
  EXPECT_TRUE(rays.occluded({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 4.1f));
  EXPECT_FALSE(rays.occluded({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 3.9f));
  EXPECT_FALSE(rays.occluded({0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.0f, 1e30f));
}

TEST(RayScene, AnEmptySceneHasNothingToHit) {
  Scene scene;
  RayScene rays(scene);
  EXPECT_FALSE(rays.intersect({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
  EXPECT_FALSE(rays.occluded({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
}

}  // namespace
}  // namespace prism::reference

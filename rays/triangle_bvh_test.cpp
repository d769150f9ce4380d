#include "rays/triangle_bvh.h"

#include <array>
#include <vector>

#include <gtest/gtest.h>

namespace prism::rays {
namespace {

// A 2 × 2 square in the plane z = zPlane, facing +z, as two triangles.
struct Square {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
  explicit Square(float zPlane)
      : positions{{-1.0f, -1.0f, zPlane}, {1.0f, -1.0f, zPlane}, {1.0f, 1.0f, zPlane}, {-1.0f, 1.0f, zPlane}} {}
};

TEST(TriangleBvh, ClosestHitNamesTheMeshTheTriangleAndWhereOnIt) {
  Square near(1.0f), far(-2.0f);
  std::array meshes{TriangleMesh{7, far.positions, far.indices}, TriangleMesh{3, near.positions, near.indices}};
  TriangleBvh bvh(meshes);
  const glm::vec3 origin(0.5f, -0.25f, 5.0f), down(0.0f, 0.0f, -1.0f);
  auto hit = bvh.intersect(origin, down, 0.0f, 1e30f);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->geometry, 3u);
  EXPECT_NEAR(hit->distance, 4.0f, 1e-5f);
  // The barycentrics give the point back on the triangle they name.
  const glm::vec3* p = near.positions.data();
  const std::uint32_t* t = near.indices.data() + 3 * hit->triangle;
  glm::vec3 onTriangle = (1.0f - hit->u - hit->v) * p[t[0]] + hit->u * p[t[1]] + hit->v * p[t[2]];
  glm::vec3 along = origin + hit->distance * down;
  EXPECT_NEAR(onTriangle.x, along.x, 1e-5f);
  EXPECT_NEAR(onTriangle.y, along.y, 1e-5f);
  EXPECT_NEAR(onTriangle.z, along.z, 1e-5f);

  // Past the near square's far side, the far one.
  auto beyond = bvh.intersect(origin, down, 4.5f, 1e30f);
  ASSERT_TRUE(beyond);
  EXPECT_EQ(beyond->geometry, 7u);
  EXPECT_NEAR(beyond->distance, 7.0f, 1e-5f);
}

TEST(TriangleBvh, RespectsTheRayIntervalAndMissesWhatIsNotThere) {
  Square square(0.0f);
  std::array meshes{TriangleMesh{0, square.positions, square.indices}};
  TriangleBvh bvh(meshes);
  const glm::vec3 origin(0.0f, 0.0f, 5.0f), down(0.0f, 0.0f, -1.0f);
  EXPECT_FALSE(bvh.intersect(origin, -down, 0.0f, 1e30f));
  EXPECT_FALSE(bvh.intersect(origin, down, 0.0f, 4.9f));
  EXPECT_FALSE(bvh.intersect({3.0f, 0.0f, 5.0f}, down, 0.0f, 1e30f));  // beside the square
  EXPECT_TRUE(bvh.occluded(origin, down, 0.0f, 5.1f));
  EXPECT_FALSE(bvh.occluded(origin, down, 0.0f, 4.9f));
  EXPECT_FALSE(bvh.occluded(origin, down, 5.1f, 1e30f));
}

TEST(TriangleBvh, MeshesWithoutTrianglesAreLeftOut) {
  Square square(0.0f);
  std::array meshes{TriangleMesh{0, square.positions, {}}, TriangleMesh{1, {}, {}}};
  TriangleBvh bvh(meshes);
  EXPECT_FALSE(bvh.intersect({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
  EXPECT_FALSE(bvh.occluded({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
  TriangleBvh none(std::span<const TriangleMesh>{});
  EXPECT_FALSE(none.occluded({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
}

TEST(TriangleBvh, AMovedBvhStillTraces) {
  Square square(0.0f);
  std::array meshes{TriangleMesh{0, square.positions, square.indices}};
  TriangleBvh first(meshes);
  TriangleBvh second = std::move(first);
  EXPECT_TRUE(second.occluded({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1e30f));
}

}  // namespace
}  // namespace prism::rays

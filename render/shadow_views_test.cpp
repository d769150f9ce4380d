// Where the shadow maps look from (render/shadow_views.h) and the point lights' faces
// (shaders/shared/shadow_filter.glsl), on the CPU: the faces are the views lookAt and perspective
// would build, every direction lands inside its face with the PCF footprint's room, and a point
// light takes six consecutive layers.
#include "render/shadow_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "render/shared_shading.h"
#include "scene/procedural_mesh.h"

namespace prism::render {
namespace {

TEST(PointShadowFaces, AreTheViewsLookAtAndPerspectiveBuild) {
  const glm::vec3 lamp(0.3f, 2.0f, -1.5f);
  const float nearM = 0.05f, farM = 12.0f;
  const int size = 1024;
  const glm::vec3 forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec3 projection = shared::pointShadowProjection(nearM, farM, size);
  const float fov = 2.0f * std::atan(1.0f / projection.x);
  for (int face = 0; face < 6; ++face) {
    const glm::vec3 up = face / 2 == 1 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 expected =
        glm::perspective(fov, 1.0f, nearM, farM) * glm::lookAt(lamp, lamp + forward[face], up);
    const glm::mat4 actual = shared::pointShadowFromWorld(lamp, face, projection);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(actual[c][r], expected[c][r], 1e-5f) << "face " << face;
    // Looking along its axis: a point ahead in the middle of the map.
    const glm::vec4 clip = actual * glm::vec4(lamp + 3.0f * forward[face], 1.0f);
    EXPECT_NEAR(clip.w, 3.0f, 1e-5f);
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-6f);
    EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-6f);
  }
}

TEST(PointShadowFaces, EveryDirectionFallsInsideItsFaceWithTheFootprintsRoom) {
  const glm::vec3 lamp(-1.0f, 0.5f, 2.0f);
  std::mt19937 rng(7);
  std::normal_distribution<float> normal;
  for (int size : {16, 512, 2048}) {
    for (int n = 0; n < 20000; ++n) {
      // Random directions, and directions on seams and corners (components tied in magnitude).
      glm::vec3 d(normal(rng), normal(rng), normal(rng));
      if (n % 4 == 1) d.y = std::copysign(std::abs(d.x), d.y);
      if (n % 4 == 2) d = glm::vec3(std::copysign(1.0f, d.x), std::copysign(1.0f, d.y), std::copysign(1.0f, d.z));
      const glm::vec3 p = lamp + glm::normalize(d) * (0.2f + std::abs(normal(rng)));  // within [near, far]
      const int face = shared::pointShadowFace(p - lamp);
      const shared::ShadowFootprint f =
          shared::shadowFootprint(shared::pointShadowFromWorld(lamp, face, shared::pointShadowProjection(0.05f, 100.0f, size)) *
                                      glm::vec4(p, 1.0f),
                                  size);
      ASSERT_TRUE(f.inside) << "size " << size << ", direction " << d.x << " " << d.y << " " << d.z;
      // The 4×4 taps from (x0, y0) need no clamping.
      EXPECT_GE(f.x0, 0);
      EXPECT_GE(f.y0, 0);
      EXPECT_LE(f.x0 + 3, size - 1);
      EXPECT_LE(f.y0 + 3, size - 1);
    }
  }
}

TEST(ShadowViews, APointLightTakesSixConsecutiveLayers) {
  Scene scene;
  scene.meshes.push_back(makeSphere({0.0f, 0.5f, 0.0f}, 0.5f));
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.0f, 3.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  Light point;
  point.type = LightType::Point;
  point.position = {1.0f, 2.0f, 1.0f};
  Light unshadowed = point;
  unshadowed.castsShadows = false;
  scene.lights = {spot, unshadowed, point};
  const std::vector<ShadowView> views = planShadowViews(scene, 256);
  ASSERT_EQ(views.size(), 7u);
  EXPECT_EQ(views[0].lightIndex, 0);
  for (int face = 0; face < 6; ++face) {
    const ShadowView& v = views[static_cast<std::size_t>(1 + face)];
    EXPECT_EQ(v.lightIndex, 2);
    EXPECT_EQ(v.layer, 1 + face);
    EXPECT_EQ(v.pointProjection, views[1].pointProjection);
    EXPECT_EQ(v.viewProjection, shared::pointShadowFromWorld(point.position, face, v.pointProjection));
  }
  // The faces' depth range holds the scene: the sphere's centre is inside its face's frustum.
  const glm::vec3 ball(0.0f, 0.5f, 0.0f);
  const ShadowView& seen = views[static_cast<std::size_t>(1 + shared::pointShadowFace(ball - point.position))];
  EXPECT_TRUE(shared::shadowFootprint(seen.viewProjection * glm::vec4(ball, 1.0f), 256).inside);
}

}  // namespace
}  // namespace prism::render

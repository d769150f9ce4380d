// Where the shadow maps look from (render/shadow_views.h) and the point lights' faces
// (shaders/shared/shadow_filter.glsl), on the CPU: the faces are the views lookAt and perspective
// would build, every direction lands inside its face with the PCF footprint's room, a point
// light takes six consecutive layers, and a scene's shadows do not depend on its unit of length.
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

// A scene in centimetres (every length a hundredth) sees its surfaces in its point and spot
// lights' maps where the scene in metres does: the cube, 2.5 cm from the lamp, was nearer than
// the maps' fixed 5 cm near plane and cast no shadow (a new-user review).
TEST(ShadowViews, AScenesShadowsDoNotDependOnItsUnitOfLength) {
  auto scene = [](float unit) {
    Scene s;
    s.meshes.push_back(makeBox(glm::vec3(0.0f, 0.5f, 0.0f) * unit, glm::vec3(1.0f) * unit));
    s.meshes.push_back(makePlane(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(4.0f) * unit));
    Light point;
    point.type = LightType::Point;
    point.position = glm::vec3(1.5f, 3.0f, 1.0f) * unit;
    Light spot = point;
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(glm::vec3(-1.5f, -2.5f, -1.0f));
    s.lights = {point, spot};
    return s;
  };
  const std::vector<ShadowView> metres = planShadowViews(scene(1.0f), 512), centimetres = planShadowViews(scene(0.01f), 512);
  ASSERT_EQ(metres.size(), centimetres.size());
  const glm::vec3 cubeTop(0.0f, 1.0f, 0.0f);
  int seen = 0;
  for (std::size_t i = 0; i < metres.size(); ++i) {
    const glm::vec4 m = metres[i].viewProjection * glm::vec4(cubeTop, 1.0f);
    const glm::vec4 c = centimetres[i].viewProjection * glm::vec4(0.01f * cubeTop, 1.0f);
    if (!shared::shadowFootprint(m, 512).inside) continue;
    ++seen;
    EXPECT_TRUE(shared::shadowFootprint(c, 512).inside) << "view " << i;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k] / c.w, m[k] / m.w, 1e-4f) << "view " << i << ", axis " << k;
    EXPECT_NEAR(centimetres[i].normalOffsetM, 0.01f * metres[i].normalOffsetM, 1e-4f * metres[i].normalOffsetM);
  }
  EXPECT_EQ(seen, 2);  // the point light's face towards it, and the spot
}

}  // namespace
}  // namespace prism::render

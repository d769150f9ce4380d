// Where the shadow maps look from (render/shadow_views.h) and the point lights' faces
// (shaders/shared/shadow_filter.glsl), on the CPU: the faces are the views lookAt and perspective
// would build, every direction lands inside its face with the PCF footprint's room, a point
// light takes six consecutive layers, and a scene's shadows do not depend on its unit of length.
#include "render/shadow_views.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// A sun over a ground 2 km wide: four layers in order, the last the whole scene's map; each
// drawn with the matrix the lighting pass looks it up with; the nearest fitted to the view near the
// camera (texels under 2 cm where the whole map's are 2.8 m), moved in whole texels of its own;
// the ground the camera sees within 8 m inside it with the PCF footprint's room. One cascade is
// the whole map alone.
TEST(ShadowViews, ADirectionalLightsCascadesAreFittedToTheViewFinestNearTheCamera) {
  Scene scene;
  scene.meshes.push_back(makePlane(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(2000.0f)));
  scene.meshes.push_back(makeSphere({0.0f, 0.5f, 0.0f}, 0.5f));
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.45f, -0.6f, -0.66f));
  scene.lights = {sun};
  ShadowCascading cascading;
  cascading.count = 4;
  cascading.camera.position = {0.0f, 2.5f, 6.0f};
  cascading.camera.target = {0.0f, 0.0f, 0.0f};
  cascading.camera.verticalFovDeg = 50.0f;
  cascading.camera.nearPlane = 0.1f;
  cascading.camera.farPlane = 200.0f;
  const int size = 1024;
  const std::vector<ShadowView> views = planShadowViews(scene, size, cascading);
  ASSERT_EQ(views.size(), 4u);
  for (std::size_t c = 0; c < views.size(); ++c) {
    const ShadowView& v = views[c];
    EXPECT_EQ(v.layer, static_cast<int>(c));
    EXPECT_EQ(v.lightFromWorld, views[0].lightFromWorld);
    EXPECT_EQ(v.viewProjection, shared::shadowCascadeFromWorld(v.lightFromWorld, v.cascadeWindow));
    if (c > 0) EXPECT_LT(v.cascadeWindow.z, views[c - 1].cascadeWindow.z) << "cascade " << c;
    const float texel = 2.0f / (v.cascadeWindow.z * static_cast<float>(size));
    for (int k = 0; k < 2; ++k) {
      const float inTexels = v.cascadeWindow[k] / texel;
      EXPECT_NEAR(inTexels, std::round(inTexels), 1e-3f * std::max(1.0f, std::abs(inTexels))) << "cascade " << c;
    }
  }
  EXPECT_EQ(views[3].cascadeWindow, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
  EXPECT_EQ(views[3].viewProjection, views[3].lightFromWorld);
  const float wholeTexelM = views[0].normalOffsetM / 1.5f;  // the whole map's texel
  EXPECT_GT(wholeTexelM, 2.7f);
  EXPECT_LT(wholeTexelM / views[0].cascadeWindow.z, 0.02f);
  for (const ShadowView& v : views) EXPECT_TRUE(v.drawn) << "layer " << v.layer;
  // The ground in view up to 8 m away: inside the nearest cascade, no tap of its footprint clamped.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> across(-1.0f, 1.0f), distance(1.0f, 8.0f);
  int inside = 0;
  for (int n = 0; n < 2000; ++n) {
    const glm::vec3 p(std::clamp(across(rng) * distance(rng), -3.0f, 3.0f), 0.0f, 6.0f - distance(rng));
    const shared::ShadowFootprint f = shared::shadowFootprint(views[0].viewProjection * glm::vec4(p, 1.0f), size);
    ASSERT_TRUE(f.inside) << p.x << " " << p.z;
    inside += f.x0 >= 0 && f.y0 >= 0 && f.x0 + 3 < size && f.y0 + 3 < size;
  }
  EXPECT_EQ(inside, 2000);
  cascading.count = 1;
  const std::vector<ShadowView> one = planShadowViews(scene, size, cascading);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].viewProjection, views[3].lightFromWorld);
  EXPECT_EQ(one[0].normalOffsetM, views[0].normalOffsetM);  // the whole map's: a cascade's is this / window.z
}

// A small scene seen from far away: every slice of the view is larger than the scene, so the
// cascades collapse onto the whole map, drawn once; lights of every kind keep their layers in
// light order, a point light's six, a directional light's four, a spot's one.
TEST(ShadowViews, CascadesCollapseOntoTheWholeMapDrawnOnce) {
  Scene scene;
  scene.meshes.push_back(makeSphere({0.0f, 0.5f, 0.0f}, 0.5f));
  scene.meshes.push_back(makePlane(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(2.0f)));
  Light point;
  point.type = LightType::Point;
  point.position = {1.0f, 2.0f, 1.0f};
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.0f, 3.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  scene.lights = {point, sun, spot};
  ShadowCascading cascading;
  cascading.count = 4;
  cascading.camera.position = {0.0f, 20.0f, 60.0f};
  cascading.camera.target = {0.0f, 0.0f, 0.0f};
  cascading.camera.verticalFovDeg = 40.0f;
  cascading.aspect = 16.0f / 9.0f;
  const std::vector<ShadowView> views = planShadowViews(scene, 512, cascading);
  ASSERT_EQ(views.size(), 11u);
  for (std::size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(views[i].layer, static_cast<int>(i));
    EXPECT_EQ(views[i].lightIndex, i < 6 ? 0 : i < 10 ? 1 : 2);
    EXPECT_EQ(views[i].drawn, i < 7 || i == 10) << "layer " << i;
  }
  for (std::size_t i = 6; i < 10; ++i) EXPECT_EQ(views[i].cascadeWindow, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
  // Near enough, the first slices are finer than the scene again: drawn, fitted.
  cascading.camera.position = {0.0f, 1.0f, 2.5f};
  const std::vector<ShadowView> near = planShadowViews(scene, 512, cascading);
  ASSERT_EQ(near.size(), 11u);
  EXPECT_GT(near[6].cascadeWindow.z, 1.0f);
  EXPECT_TRUE(near[6].drawn);
}

}  // namespace
}  // namespace prism::render

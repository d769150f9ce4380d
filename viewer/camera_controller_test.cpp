#include "viewer/camera_controller.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prism::viewer {
namespace {

Camera start() {
  Camera c;
  c.position = {0.0f, 1.0f, 5.0f};
  c.target = {0.0f, 1.0f, 0.0f};
  return c;
}

TEST(CameraController, OrbitKeepsTheDistanceAndTheTarget) {
  CameraController c(start());
  c.orbit(0.7f, 0.3f);
  EXPECT_NEAR(glm::length(c.camera().position - c.camera().target), 5.0f, 1e-4f);
  EXPECT_EQ(c.camera().target, start().target);
  EXPECT_GT(c.camera().position.y, 1.0f + 1.0f) << "a positive pitch lifts the camera";
  c.orbit(0.0f, 10.0f);  // far past the pole: clamped short of it
  EXPECT_LT(c.camera().position.y - 1.0f, 5.0f);
  EXPECT_GT(glm::length(glm::vec2(c.camera().position.x, c.camera().position.z)), 0.05f);
}

TEST(CameraController, DollyPanFlyAndLookMoveAsNamedAndResetRestores) {
  CameraController c(start());
  c.dolly(0.5f);
  EXPECT_NEAR(c.camera().position.z, 2.5f, 1e-5f);
  c.pan(0.1f, 0.0f);  // right of a camera looking down −z is +x; a tenth of the 2.5 m distance
  EXPECT_NEAR(c.camera().position.x, 0.25f, 1e-5f);
  EXPECT_NEAR(c.camera().target.x, 0.25f, 1e-5f);
  c.fly({0.0f, 0.0f, 1.0f});
  EXPECT_NEAR(c.camera().position.z, 1.5f, 1e-5f);
  glm::vec3 before = c.camera().position;
  c.look(0.5f, 0.0f);
  EXPECT_EQ(c.camera().position, before);
  c.setFieldOfView(500.0f);
  EXPECT_FLOAT_EQ(c.camera().verticalFovDeg, 150.0f);
  c.reset();
  EXPECT_EQ(c.camera().position, start().position);
  EXPECT_FLOAT_EQ(c.camera().verticalFovDeg, start().verticalFovDeg);
}

TEST(CameraController, LookingStraightDownStillPansAndFlies) {
  Camera down;
  down.position = {0.0f, 5.0f, 0.0f};
  down.target = {0.0f, 0.0f, 0.0f};
  down.up = {0.0f, 0.0f, -1.0f};
  CameraController c(down);
  c.pan(0.1f, 0.0f);
  c.fly({1.0f, 0.0f, 0.0f});
  EXPECT_TRUE(std::isfinite(c.camera().position.x) && std::isfinite(c.camera().target.z));
  EXPECT_NEAR(c.camera().position.y, 5.0f, 1e-5f);
  EXPECT_GT(std::abs(c.camera().position.x) + std::abs(c.camera().position.z), 1.0f);
}

}  // namespace
}  // namespace prism::viewer

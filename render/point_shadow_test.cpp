// Point lights' shadows on the GPU (llvmpipe in CI): six faces of the shadow-map array, one
// looked up per receiver by the direction's largest component (shared::pointShadowFace). Held to
// geometry: with shadows over without, each floor pixel keeps 0 of the lamp's light where its
// segment to the lamp clearly crosses a sphere and all of it where it clearly misses; on five
// faces, seams included. (The twin test holds the same frames to the CPU, pixel by pixel.)
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "gpu/headless_context.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/renderer.h"
#include "render/shared_shading.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"

namespace prism::render {
namespace {

struct Ball {
  glm::vec3 centre;
  float radius;
};
// render/tests/point_lamp.json's lamp and spheres.
const glm::vec3 kLamp(0.0f, 1.2f, 0.0f);
const std::array<Ball, 5> kBalls{{{{2.5f, 0.4f, 0.0f}, 0.4f},
                                      {{-2.5f, 0.4f, 0.0f}, 0.4f},
                                      {{0.0f, 0.4f, 2.5f}, 0.4f},
                                      {{0.0f, 0.4f, -2.5f}, 0.4f},
                                      {{0.5f, 0.35f, -0.3f}, 0.35f}}};
// Clearly: beyond the PCF footprint, the normal offset and the spheres' tessellation, with room.
constexpr float kMarginM = 0.04f;

// The smallest distance from a sphere's centre to the segment p → lamp, less its radius.
float clearance(const glm::vec3& p) {
  float nearest = 1e30f;
  for (const Ball& b : kBalls) {
    const glm::vec3 d = kLamp - p;
    const float t = glm::clamp(glm::dot(b.centre - p, d) / glm::dot(d, d), 0.0f, 1.0f);
    nearest = std::min(nearest, glm::length(p + t * d - b.centre) - b.radius);
  }
  return nearest;
}

TEST(PointShadows, FloorPixelsSeeTheLampExactlyWhereTheSpheresDoNotHideIt) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "point_lamp.json");
  ASSERT_EQ(scene.lights.size(), 1u);
  ASSERT_EQ(scene.lights[0].position, kLamp);
  FrameSettings settings;
  settings.width = settings.height = 256;
  settings.sampling.count = 4;
  settings.sampling.strategy = SamplingStrategy::Uniform;
  settings.shadowMapSize = 1024;
  auto render = [&](bool shadows) {
    Scene s = scene;
    s.lights[0].castsShadows = shadows;
    Renderer renderer(s, cachedTestTable(), settings);
    renderer.renderFrame();
    return std::pair{GBufferReadback(renderer), renderer.frameData().constants.inverseViewProjection};
  };
  const auto [shadowed, inverseViewProjection] = render(true);
  const auto [open, unused] = render(false);

  std::array<int, 6> hidden{}, seen{};
  int floor = 0;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      const auto i = static_cast<std::size_t>(y * settings.width + x);
      const glm::vec3 p = shadowed.worldPosition(x, y, settings.width, settings.height, inverseViewProjection);
      if (shadowed.ids[i] == 0 || std::abs(p.y) > 1e-3f) continue;  // the floor only
      ++floor;
      const float lit = shadowed.accumulated(i).y, all = open.accumulated(i).y;
      ASSERT_GT(all, 0.0f) << x << ", " << y;
      const int face = shared::pointShadowFace(p - kLamp);
      const float c = clearance(p);
      if (c < -kMarginM) {
        ++hidden[static_cast<std::size_t>(face)];
        EXPECT_LE(lit / all, 0.01f) << "pixel " << x << ", " << y << " (face " << face << ") should be in shadow";
      } else if (c > kMarginM) {
        ++seen[static_cast<std::size_t>(face)];
        EXPECT_GE(lit / all, 0.99f) << "pixel " << x << ", " << y << " (face " << face << ") should be lit";
      }
    }
  }
  std::printf("floor pixels %d; in shadow by face (+x −x +y −y +z −z):", floor);
  for (int n : hidden) std::printf(" %d", n);
  std::printf("; lit:");
  for (int n : seen) std::printf(" %d", n);
  std::printf("\n");
  for (int face : {0, 1, 3, 4, 5}) {  // the floor is below the lamp: never the +y face
    EXPECT_GE(hidden[static_cast<std::size_t>(face)], 100) << "face " << face;
    EXPECT_GE(seen[static_cast<std::size_t>(face)], 100) << "face " << face;
  }
}

}  // namespace
}  // namespace prism::render

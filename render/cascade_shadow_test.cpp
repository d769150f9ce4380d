// A directional light's cascaded shadow maps on the GPU (llvmpipe in CI), held to geometry: on a
// ground 2 km wide, each ground pixel keeps none of the sun's light where its ray to the sun
// clearly crosses a ball and all of it where it clearly misses, with four cascades; with one map
// over the whole ground (texels of 2.8 m) most of the balls' shadows are lost. (The twin test holds
// the same frame to the CPU, pixel by pixel.)
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
namespace wide_ground {  // the target's files share one unity translation unit

struct Ball {
  glm::vec3 centre;
  float radius;
};
// render/tests/sun_wide_ground.json's balls.
const std::array<Ball, 3> kBalls{{{{-1.2f, 0.5f, 0.0f}, 0.5f}, {{0.6f, 0.3f, 1.2f}, 0.3f}, {{1.0f, 0.5f, -2.0f}, 0.5f}}};
// Clearly, across the ray: beyond the nearest cascade's PCF reach (2 texels of 1.9 cm here: a
// slice 9.5 m in radius over 1024 texels), its normal offset (1.5 texels) and the balls'
// tessellation, with room.
constexpr float kMarginM = 0.08f;

// The smallest distance from a ball's centre to the ray from p towards the sun, less its radius.
float clearance(const glm::vec3& p, const glm::vec3& toSun) {
  float nearest = 1e30f;
  for (const Ball& b : kBalls) {
    const float t = std::max(glm::dot(b.centre - p, toSun), 0.0f);
    nearest = std::min(nearest, glm::length(p + t * toSun - b.centre) - b.radius);
  }
  return nearest;
}

struct Counts {
  int hidden = 0, hiddenDark = 0, seen = 0, seenLit = 0;
};

Counts countGround(int cascades) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "sun_wide_ground.json");
  const glm::vec3 toSun = -glm::normalize(scene.lights.at(0).direction);
  FrameSettings settings;
  settings.width = settings.height = 256;
  settings.sampling.count = 4;
  settings.sampling.strategy = SamplingStrategy::Uniform;
  settings.shadowMapSize = 1024;
  settings.shadowCascades = cascades;
  auto render = [&](bool shadows) {
    Scene s = scene;
    s.lights[0].castsShadows = shadows;
    Renderer renderer(s, cachedTestTable(), settings);
    renderer.renderFrame();
    if (shadows) {
      // The lighting pass's record of the sun: its first layer and a window per layer drawn.
      const shared::GpuLight& sun = renderer.frameData().lights.at(0);
      const std::vector<ShadowView>& views = renderer.shadowViews();
      EXPECT_EQ(views.size(), static_cast<std::size_t>(cascades));
      EXPECT_EQ(sun.shadowLayer, views.at(0).layer);
      EXPECT_EQ(sun.shadowCascadeCount, cascades);
      for (int c = 0; c < sun.shadowCascadeCount; ++c) {
        EXPECT_TRUE(views.at(static_cast<std::size_t>(c)).drawn);
        EXPECT_EQ(sun.shadowCascades[c], views.at(static_cast<std::size_t>(c)).cascadeWindow) << "cascade " << c;
      }
    }
    return std::pair{GBufferReadback(renderer), renderer.frameData().constants.inverseViewProjection};
  };
  const auto [shadowed, inverseViewProjection] = render(true);
  const auto [open, unused] = render(false);
  Counts counts;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      const auto i = static_cast<std::size_t>(y * settings.width + x);
      const glm::vec3 p = shadowed.worldPosition(x, y, settings.width, settings.height, inverseViewProjection);
      if (shadowed.ids[i] == 0 || std::abs(p.y) > 1e-3f) continue;  // the ground only
      const float lit = shadowed.accumulated(i).y, all = open.accumulated(i).y;
      if (!(all > 0.0f)) {
        ADD_FAILURE() << "ground pixel " << x << ", " << y << " gets no sunlight without shadows";
        continue;
      }
      const float c = clearance(p, toSun);
      if (c < -kMarginM) {
        ++counts.hidden;
        counts.hiddenDark += lit / all <= 0.01f;
      } else if (c > kMarginM) {
        ++counts.seen;
        counts.seenLit += lit / all >= 0.99f;
      }
    }
  }
  std::printf("%d cascade(s): %d of %d ground pixels behind a ball in shadow, %d of %d in the clear lit\n", cascades,
              counts.hiddenDark, counts.hidden, counts.seenLit, counts.seen);
  return counts;
}

}  // namespace wide_ground

TEST(CascadedShadows, ASmallObjectsShadowHoldsOnAWideGround) {
  const wide_ground::Counts four = wide_ground::countGround(4);
  EXPECT_GE(four.hidden, 300);  // enough of the balls' shadows in view to hold
  EXPECT_GE(four.seen, 5000);
  EXPECT_EQ(four.hiddenDark, four.hidden);
  EXPECT_EQ(four.seenLit, four.seen);
  // One map over the whole ground: the balls are smaller than its texels.
  const wide_ground::Counts one = wide_ground::countGround(1);
  EXPECT_LT(one.hiddenDark, one.hidden / 2);
}

}  // namespace
}  // namespace prism::render

// A torch's beam under water is shadowed: the lamp's shadow map dims the light it scatters into
// the view (shared/underwater_lamps.glsl through pixel_shading.glsl's lampsInWater), so the beam
// stops at a wall in its way, and is what it was before the wall. (Unshadowed, it went on through
// the wall: 5.4 mean ΔE00 from the path tracer behind one.)
#include <gtest/gtest.h>

#include <cstdio>

#include "gpu/headless_context.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"

namespace prism::render {
namespace {

TEST(WaterBeam, StopsAtAWallInItsWay) {
  gpu::HeadlessContext context;
  // The torch at x = −3 shines along +x; the wall across its beam at x = −1 is seen edge on, the
  // floor 1 m below the beam.
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "water_beam.json");
  FrameSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.shadowMapSize = 1024;
  auto render = [&](bool shadows) {
    Scene s = scene;
    s.lights[0].castsShadows = shadows;
    Renderer renderer(s, cachedTestTable(), settings);
    renderer.renderFrame();
    return std::pair{GBufferReadback(renderer), renderer.cameraTransform().viewProjection};
  };
  const auto [shadowed, shadowedViewProjection] = render(true);
  const auto [open, unused] = render(false);
  const glm::mat4 viewProjection = shadowedViewProjection;  // (a lambda captures no structured binding)
  // The pixel a point of the beam's axis is seen at: its ray crosses the beam there alone (the
  // camera looks across it).
  auto seenAt = [&](float x) {
    const glm::vec4 clip = viewProjection * glm::vec4(x, 0.0f, 0.0f, 1.0f);
    const glm::vec2 uv = (glm::vec2(clip) / clip.w) * 0.5f + 0.5f;
    return static_cast<std::size_t>(static_cast<int>(uv.y * static_cast<float>(settings.height)) * settings.width +
                                    static_cast<int>(uv.x * static_cast<float>(settings.width)));
  };
  for (float x : {-2.5f, -2.0f, -1.5f}) {  // before the wall: as lit with its shadow as without
    const std::size_t i = seenAt(x);
    std::printf("x = %g m, before the wall: Y %.5g shadowed, %.5g open\n", x, shadowed.accumulated(i).y,
                open.accumulated(i).y);
    EXPECT_GT(open.accumulated(i).y, 0.0f);
    EXPECT_NEAR(shadowed.accumulated(i).y, open.accumulated(i).y, 1e-3f * open.accumulated(i).y) << x;
  }
  for (float x : {-0.5f, 0.0f, 1.0f, 2.0f}) {  // behind it: dark
    const std::size_t i = seenAt(x);
    std::printf("x = %g m, behind the wall: Y %.5g shadowed, %.5g open\n", x, shadowed.accumulated(i).y,
                open.accumulated(i).y);
    EXPECT_GT(open.accumulated(i).y, 0.0f);
    EXPECT_LT(shadowed.accumulated(i).y, 0.01f * open.accumulated(i).y) << x;
  }
}

}  // namespace
}  // namespace prism::render

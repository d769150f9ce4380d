// A torch's beam under water is shadowed: the lamp's shadow map dims the light it scatters into
// the view (shared/underwater_lamps.glsl through pixel_shading.glsl's lampsInWater), so the beam
// stops at a wall in its way, and is what it was before the wall. (Unshadowed, it went on through
// the wall: this fixture was 0.95 mean ΔE00 from the path tracer, p99 25.7; now 0.39, p99 0.)
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "gpu/headless_context.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"

namespace prism::render {
namespace {

// The beam's Y at points of its axis (y = z = 0) at these x, as the view sees them (the camera
// looks across the beam, so each one's ray crosses it there alone), with the torch's shadow and
// without.
struct BeamSeen {
  std::vector<float> shadowed, open;
};
BeamSeen beamAt(const std::vector<std::string>& sets, const std::vector<float>& xs) {
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "water_beam.json", sets);
  FrameSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.shadowMapSize = 1024;
  BeamSeen seen;
  for (bool shadows : {true, false}) {
    Scene s = scene;
    s.lights[0].castsShadows = shadows;
    Renderer renderer(s, cachedTestTable(), settings);
    renderer.renderFrame();
    const GBufferReadback g(renderer);
    for (float x : xs) {
      const glm::vec4 clip = renderer.cameraTransform().viewProjection * glm::vec4(x, 0.0f, 0.0f, 1.0f);
      const glm::vec2 uv = (glm::vec2(clip) / clip.w) * 0.5f + 0.5f;
      const auto i = static_cast<std::size_t>(static_cast<int>(uv.y * static_cast<float>(settings.height)) * settings.width +
                                              static_cast<int>(uv.x * static_cast<float>(settings.width)));
      (shadows ? seen.shadowed : seen.open).push_back(g.accumulated(i).y);
    }
  }
  return seen;
}

// The torch at x = −3 shines along +x; the wall across its beam at x = −1 is seen edge on, the
// floor 1 m below the beam. Before the wall the beam is as lit with its shadow as without; behind
// it, dark.
TEST(WaterBeam, StopsAtAWallInItsWay) {
  gpu::HeadlessContext context;
  const std::vector<float> xs{-2.5f, -2.0f, -1.5f, -0.5f, 0.0f, 1.0f, 2.0f};
  const BeamSeen seen = beamAt({}, xs);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    std::printf("x = %g m: Y %.5g shadowed, %.5g open\n", xs[k], seen.shadowed[k], seen.open[k]);
    EXPECT_GT(seen.open[k], 0.0f);
    if (xs[k] < -1.0f) EXPECT_NEAR(seen.shadowed[k], seen.open[k], 1e-3f * seen.open[k]) << xs[k];
    else EXPECT_LT(seen.shadowed[k], 0.01f * seen.open[k]) << xs[k];
  }
}

// With a floor of 6 × 6 m the scene's bounds put the shadow map's far plane 7.4 m from the torch:
// the beam beyond it, 8 and 9 m on behind the wall, is dark too (it was taken as lit, outside the
// map, and went on there).
TEST(WaterBeam, StaysDarkBeyondTheShadowMapsFarPlane) {
  gpu::HeadlessContext context;
  const std::vector<float> xs{5.0f, 6.0f};
  const BeamSeen seen = beamAt({"objects.1.plane.size=[6,6]", "camera.position=[0,0.5,9]"}, xs);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    std::printf("x = %g m: Y %.5g shadowed, %.5g open\n", xs[k], seen.shadowed[k], seen.open[k]);
    EXPECT_GT(seen.open[k], 0.0f);
    EXPECT_LT(seen.shadowed[k], 0.01f * seen.open[k]) << xs[k];
  }
}

}  // namespace
}  // namespace prism::render

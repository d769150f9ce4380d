// What a frame draws again and what it keeps: settings that restart accumulation or only change
// the display, the shadow maps and G-buffer drawn only on a restart, and of the shadow maps only
// those whose view moved, each frame bit for bit what a new renderer makes.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "gpu/headless_context.h"
#include "render/small_frame_test_support.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"

namespace prism::render {
namespace {
namespace restart {  // the target's files share one unity translation unit

const std::filesystem::path kScenes = PRISM_SCENES_DIR;

TEST(Renderer, SettingsChangeWithoutRestartAndRestartAccumulation) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kScenes / "spheres_d65.json");
  Renderer renderer(scene, cachedTestTable(), smallFrame(RenderMode::Rgb));
  renderer.renderFrame();
  renderer.renderFrame();
  EXPECT_EQ(renderer.accumulatedFrames(), 2);
  FrameSettings bigger = smallFrame(RenderMode::JakobHanika, 32);
  bigger.width = 96;
  bigger.height = 64;
  renderer.setSettings(bigger);
  EXPECT_EQ(renderer.accumulatedFrames(), 0);
  renderer.renderFrame();
  EXPECT_EQ(renderer.accumulation().width(), 96);
  EXPECT_EQ(renderer.accumulation().height(), 64);
  EXPECT_EQ(renderer.readDisplayRgba8().size(), std::size_t{96 * 64 * 4});
  // A display-only change keeps what has accumulated, and the wavelength sampler (making one
  // reads the fitted set again); a failed change leaves all as it was.
  const std::shared_ptr<const WavelengthSampler> sampler = renderer.context().wavelengths;
  bigger.display.toneMap = ToneMap::Reinhard;
  bigger.display.ev100 = 12.0f;
  renderer.setSettings(bigger);
  EXPECT_EQ(renderer.accumulatedFrames(), 1);
  EXPECT_EQ(renderer.context().wavelengths, sampler);
  FrameSettings bad = bigger;
  bad.display.whiteBalance = "no-such-lamp";
  EXPECT_THROW(renderer.setSettings(bad), Error);
  EXPECT_EQ(renderer.settings().display.whiteBalance, "none");
  renderer.renderFrame();
  EXPECT_EQ(renderer.accumulatedFrames(), 2);
  EXPECT_EQ(renderer.frameData().batches.size(), std::size_t{8});
  // Another count or observer makes a sampler of its own.
  bigger.sampling.count = 16;
  renderer.setSettings(bigger);
  const std::shared_ptr<const WavelengthSampler> sixteen = renderer.context().wavelengths;
  EXPECT_EQ(sixteen->settings().count, 16);
  bigger.observer = "cie1964";
  renderer.setSettings(bigger);
  EXPECT_NE(renderer.context().wavelengths, sixteen);
  renderer.renderFrame();
  EXPECT_EQ(renderer.frameData().batches.size(), std::size_t{4});
}

// Frames that accumulate light what the frame that restarted drew into the shadow maps and the
// G-buffer: under the same wavelengths every frame, the second adds exactly what the first did.
TEST(Renderer, OnlyARestartDrawsTheShadowMapsAndTheGBuffer) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kScenes / "spheres_d65.json");
  FrameSettings settings = smallFrame(RenderMode::JakobHanika);
  settings.sampling.strategy = SamplingStrategy::Uniform;
  Renderer renderer(scene, cachedTestTable(), settings);
  ASSERT_FALSE(renderer.shadowViews().empty());
  std::vector<std::string> passes;
  renderer.setPassHook([&](std::string_view pass) { passes.emplace_back(pass); });
  auto frame = [&] {
    passes.clear();
    renderer.renderFrame();
    return std::count(passes.begin(), passes.end(), "shadow") + std::count(passes.begin(), passes.end(), "gbuffer");
  };
  EXPECT_EQ(frame(), 2);
  const std::vector<float> first = renderer.readMeanTristimulus();
  EXPECT_EQ(frame(), 0);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "lighting"), 1);
  EXPECT_EQ(renderer.accumulatedFrames(), 2);
  EXPECT_EQ(renderer.readMeanTristimulus(), first);
  // Whatever restarts accumulation draws them again; a display-only change does not.
  settings.display.toneMap = ToneMap::Reinhard;
  renderer.setSettings(settings);
  EXPECT_EQ(frame(), 0);
  renderer.setCamera(renderer.camera());
  EXPECT_EQ(frame(), 2);
  renderer.sceneChanged();
  EXPECT_EQ(frame(), 2);
  settings.sampling.count = 8;
  renderer.setSettings(settings);
  EXPECT_EQ(frame(), 2);
  renderer.resetAccumulation();
  EXPECT_EQ(frame(), 2);
  EXPECT_EQ(frame(), 0);
  // An edited material reaches the image through the G-buffer drawn again after sceneChanged.
  const std::vector<float> before = renderer.readMeanTristimulus();
  for (Material& m : scene.materials) m.baseColour = glm::vec3(1.0f) - m.baseColour;
  renderer.sceneChanged();
  EXPECT_EQ(frame(), 2);
  EXPECT_NE(renderer.readMeanTristimulus(), before);
}

// A restart draws again only the shadow maps whose view moved: none for new settings or the same
// camera; the sun's cascades, not its whole-scene map nor the spot's, for a moved camera; the
// sun's for a turned sun; all of them when the layers change in number and after
// resetAccumulation. Each frame is, bit for bit, the
// one a new renderer, which draws every map, makes there.
TEST(Renderer, AShadowMapIsDrawnAgainOnlyWhenItsViewMoves) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kScenes / "textured_gltf.json");  // a spot, then the sun
  ASSERT_EQ(scene.lights.at(1).type, LightType::Directional);
  FrameSettings settings = smallFrame(RenderMode::JakobHanika);
  settings.sampling.strategy = SamplingStrategy::Uniform;
  Renderer renderer(scene, cachedTestTable(), settings);
  auto drawnLayers = [&](int light) {
    return static_cast<int>(std::count_if(renderer.shadowViews().begin(), renderer.shadowViews().end(), [&](const ShadowView& v) {
      return v.drawn && (light < 0 || v.lightIndex == light);
    }));
  };
  auto framed = [&] {
    renderer.renderFrame();
    return renderer.shadowLayersDrawn();
  };
  auto asNew = [&](const char* what) {
    Renderer fresh(scene, cachedTestTable(), settings);
    fresh.setCamera(renderer.camera());
    fresh.renderFrame();
    EXPECT_EQ(fresh.shadowLayersDrawn(), drawnLayers(-1)) << what;
    EXPECT_EQ(renderer.readMeanTristimulus(), fresh.readMeanTristimulus()) << what;
  };
  EXPECT_EQ(framed(), drawnLayers(-1));
  ASSERT_GE(drawnLayers(1), 3);  // the spot's map and the sun's cascades, none collapsed
  EXPECT_EQ(framed(), 0);        // accumulating
  settings.sampling.count = 8;
  renderer.setSettings(settings);
  EXPECT_EQ(framed(), 0);
  renderer.setCamera(renderer.camera());
  EXPECT_EQ(framed(), 0);

  Camera moved = renderer.camera();
  moved.position += glm::vec3(0.3f, 0.2f, -0.4f);
  renderer.setCamera(moved);
  const int afterMove = framed();
  EXPECT_GT(afterMove, 0);
  EXPECT_LE(afterMove, drawnLayers(1) - 1);  // neither the spot's map nor the sun's whole-scene one
  asNew("moved camera");

  scene.lights[1].direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.1f));
  renderer.sceneChanged();
  EXPECT_EQ(framed(), drawnLayers(1));
  asNew("turned sun");

  // Fewer layers (the sun's cascades, the spot's map gone) are maps made again: all drawn.
  settings.shadowCascades = 2;
  renderer.setSettings(settings);
  EXPECT_EQ(framed(), drawnLayers(-1));
  asNew("two cascades");
  scene.lights[0].castsShadows = false;
  renderer.sceneChanged();
  EXPECT_EQ(framed(), drawnLayers(-1));
  asNew("a spot without shadows");

  renderer.resetAccumulation();
  EXPECT_EQ(framed(), drawnLayers(-1));
}

}  // namespace restart
}  // namespace
}  // namespace prism::render

#include "viewer/viewer_settings.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"

namespace prism::viewer {
namespace {

TEST(ViewerSettings, EveryFrameKeyReadsBackWhatItWrote) {
  render::FrameSettings s;
  ASSERT_TRUE(applyFrameSetting(s, "mode", "naive"));
  ASSERT_TRUE(applyFrameSetting(s, "wavelengths", "32"));
  ASSERT_TRUE(applyFrameSetting(s, "range", "380,720"));
  ASSERT_TRUE(applyFrameSetting(s, "strategy", "rotated"));
  ASSERT_TRUE(applyFrameSetting(s, "gbuffer", "coefficients"));
  ASSERT_TRUE(applyFrameSetting(s, "ev", "9.5"));
  EXPECT_FALSE(applyFrameSetting(s, "colour", "red"));
  render::FrameSettings again;
  for (const auto& [key, value] : frameSettingValues(s)) ASSERT_TRUE(applyFrameSetting(again, key, value)) << key;
  EXPECT_EQ(frameSettingValues(again), frameSettingValues(s));
  EXPECT_EQ(again.sampling.count, 32);
  EXPECT_DOUBLE_EQ(again.sampling.minNm, 380.0);
  ASSERT_TRUE(again.ev100);
  EXPECT_FLOAT_EQ(*again.ev100, 9.5f);
  EXPECT_THROW(applyFrameSetting(s, "wavelengths", "many"), Error);
  EXPECT_THROW(applyFrameSetting(s, "mode", "sepia"), Error);
}

TEST(ViewerSettings, FilesRoundTripAndBadOnesChangeNothing) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "viewer_settings";
  std::filesystem::create_directories(dir);
  ViewSettings view;
  view.left.mode = render::RenderMode::Rgb;
  view.right.sampling.count = 64;
  view.split = true;
  Camera camera;
  camera.position = {1.0f, 2.0f, 3.0f};
  camera.verticalFovDeg = 60.0f;
  saveViewSettings(dir / "s.json", view, camera);
  ViewSettings loaded;
  Camera loadedCamera;
  loadViewSettings(dir / "s.json", loaded, loadedCamera);
  EXPECT_EQ(loaded.left.mode, render::RenderMode::Rgb);
  EXPECT_EQ(loaded.right.sampling.count, 64);
  EXPECT_TRUE(loaded.split);
  EXPECT_EQ(loadedCamera.position, camera.position);
  EXPECT_FLOAT_EQ(loadedCamera.verticalFovDeg, 60.0f);

  std::ofstream(dir / "bad.json") << R"({"left": {"wavelengths": "6"}, "split": false})";
  try {
    loadViewSettings(dir / "bad.json", loaded, loadedCamera);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json: /left: wavelength count must be a multiple of 4"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(loaded.split) << "a failed load changes nothing";
  std::ofstream(dir / "unknown.json") << R"({"lefty": {}})";
  EXPECT_THROW(loadViewSettings(dir / "unknown.json", loaded, loadedCamera), Error);
}

}  // namespace
}  // namespace prism::viewer

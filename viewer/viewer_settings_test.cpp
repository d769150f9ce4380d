#include "viewer/viewer_settings.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "render/setting_keys.h"

namespace prism::viewer {
namespace {

TEST(ViewerSettings, EveryFrameKeyReadsBackWhatItWrote) {
  render::FrameSettings s;
  for (const render::SettingKey& key : render::frameSettingKeys()) {
    ASSERT_TRUE(render::applyFrameSetting(s, key.name, key.example)) << key.name;
  }
  EXPECT_FALSE(render::applyFrameSetting(s, "colour", "red"));
  render::FrameSettings again;
  for (const auto& [key, value] : render::frameSettingValues(s)) {
    ASSERT_TRUE(render::applyFrameSetting(again, key, value)) << key;
  }
  EXPECT_EQ(render::frameSettingValues(again), render::frameSettingValues(s));
  EXPECT_EQ(again.sampling.count, 32);
  EXPECT_DOUBLE_EQ(again.sampling.minNm, 380.0);
  ASSERT_TRUE(again.display.ev100);
  EXPECT_FLOAT_EQ(*again.display.ev100, 9.5f);
  EXPECT_THROW(render::applyFrameSetting(s, "wavelengths", "many"), Error);
  EXPECT_THROW(render::applyFrameSetting(s, "mode", "sepia"), Error);
  // A leading '+', which the command line's decimal check lets through, as every other number
  // option takes it (--width +64 was refused where --frames +64 was read).
  ASSERT_TRUE(render::applyFrameSetting(again, "width", "+64"));
  EXPECT_EQ(again.width, 64);
  ASSERT_TRUE(render::applyFrameSetting(again, "ev", "+2.5"));
  EXPECT_FLOAT_EQ(*again.display.ev100, 2.5f);
  EXPECT_THROW(render::applyFrameSetting(again, "width", "+"), Error);
}

TEST(ViewerSettings, BadValuesAreOneLineNamingTheKeyAndWhatItExpects) {
  render::FrameSettings s;
  auto message = [&](const char* key, const char* value) {
    try {
      render::applyFrameSetting(s, key, value);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("mode", "sepia"), "mode: expected rgb, naive, jakob-hanika, reference or optimised4, got \"sepia\"");
  EXPECT_EQ(message("gizmos", "yes"), "gizmos: expected on or off, got \"yes\"");
  EXPECT_EQ(message("shadow-map-size", "8"), "shadow-map-size: expected a whole number within 16–8192, got \"8\"");
  EXPECT_EQ(message("observer", "cie1932"), "observer: unknown observer 'cie1932' (see `prism colour list observers`)");
  EXPECT_EQ(message("white-balance", "f11"), "white-balance: unknown illuminant 'f11' (did you mean 'F11'?) (see `prism colour list illuminants`)");
  EXPECT_EQ(render::frameSettingValues(s), render::frameSettingValues(render::FrameSettings{})) << "nothing changed";
}

TEST(ViewerSettings, ViewKeysSetEitherHalfAndTheSplit) {
  ViewSettings view;
  EXPECT_TRUE(applyViewSetting(view, "mode", "rgb"));
  EXPECT_TRUE(applyViewSetting(view, "right.tonemap", "none"));
  EXPECT_TRUE(applyViewSetting(view, "split", "on"));
  EXPECT_FALSE(applyViewSetting(view, "fov", "40"));
  EXPECT_THROW(applyViewSetting(view, "right.fov", "40"), Error);
  EXPECT_EQ(view.left.mode, render::RenderMode::Rgb);
  EXPECT_EQ(view.right.mode, render::RenderMode::JakobHanika);
  EXPECT_EQ(view.right.display.toneMap, render::ToneMap::None);
  EXPECT_TRUE(view.split);
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
    EXPECT_NE(std::string(e.what()).find("bad.json: /left/wavelengths: wavelengths: expected a multiple of 4 within 4–1000, got \"6\""), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(loaded.split) << "a failed load changes nothing";
  // Written by hand: numbers, true/false and a range as an array mean what their text does.
  std::ofstream(dir / "hand.json") << R"({"left": {"wavelengths": 32, "ev": 9.5, "gizmos": true, "range": [380, 720]}})";
  loadViewSettings(dir / "hand.json", loaded, loadedCamera);
  EXPECT_EQ(loaded.left.sampling.count, 32);
  EXPECT_EQ(loaded.left.display.ev100, 9.5f);
  EXPECT_TRUE(loaded.left.lightGizmos);
  EXPECT_EQ(loaded.left.sampling.minNm, 380.0);
  EXPECT_EQ(loaded.left.sampling.maxNm, 720.0);
  std::ofstream(dir / "object.json") << R"({"left": {"range": {"min": 380}}})";
  try {
    loadViewSettings(dir / "object.json", loaded, loadedCamera);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("object.json: /left/range: expected a string, a number"), std::string::npos)
        << e.what();
  }
  // An array is a range's alone: [8] was read as 8 wavelengths.
  std::ofstream(dir / "listed.json") << R"({"left": {"wavelengths": [8]}})";
  try {
    loadViewSettings(dir / "listed.json", loaded, loadedCamera);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("listed.json: /left/wavelengths: expected a string, a number, true or false, got [8]"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(loaded.left.sampling.count, 32) << "a failed load changes nothing";
  std::ofstream(dir / "unknown.json") << R"({"lefty": {}})";
  EXPECT_THROW(loadViewSettings(dir / "unknown.json", loaded, loadedCamera), Error);
  // The camera as a scene's: a field of view of 1e-30 and a position of 1e15 were taken, 1e30 was
  // refused as a target equal to the position.
  auto cameraError = [&](const std::string& json) {
    std::ofstream(dir / "camera.json") << R"({"camera": )" + json + "}";
    try {
      loadViewSettings(dir / "camera.json", loaded, loadedCamera);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(cameraError(R"({"fov_deg": 1e-30})").find("/camera/fov_deg: expected degrees in [0.001, 180), got 1e-30"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"fov": 40})").find("/camera/fov: unknown key (allowed: position, target, up, fov_deg)"),
            std::string::npos);
  EXPECT_EQ(cameraError(R"({"fov_deg": 179.99})"), "loaded");
  EXPECT_NE(cameraError(R"({"position": [1e15, 0, 1]})").find("/camera/position: expected [x, y, z], each within ±1e+12"),
            std::string::npos)
      << cameraError(R"({"position": [1e15, 0, 1]})");
}

}  // namespace
}  // namespace prism::viewer

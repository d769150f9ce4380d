// The scene loader tests' folder of their own (SceneFolder: a temporary scene folder per test,
// files written into it, a minimal valid scene to splice into) and message matchers.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace prism::testing_support {

namespace fs = std::filesystem;

inline const fs::path kFixtures = PRISM_SCENE_TEST_DIR;

inline ::testing::AssertionResult startsWith(const std::string& text, const std::string& prefix) {
  if (text.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\n  message: " << text << "\n  expected to start with: " << prefix;
}

inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\n  message: " << text << "\n  expected to contain: " << part;
}

// A scene folder of its own per test, with files written into it.
class SceneFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    mDir = fs::path(::testing::TempDir()) / "prism_scene_test" / info->name() / "scene";
    fs::remove_all(mDir.parent_path());
    fs::create_directories(mDir);
  }
  fs::path write(const std::string& name, const std::string& text) {
    fs::path p = mDir / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  void copyFixture(const std::string& name) { fs::copy_file(kFixtures / name, mDir / name); }
  // A minimal valid scene with `materials`, `lights` and `objects` spliced in.
  fs::path scene(const std::string& materials, const std::string& lights, const std::string& objects) {
    return write("scene.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
  "materials": {)" + materials + R"(},
  "lights": [)" + lights + R"(],
  "objects": [)" + objects + "]}\n");
  }
  fs::path sceneWithLight(const std::string& light) { return scene(R"("m": {})", light, ""); }
  fs::path sceneWithMaterial(const std::string& material) {
    return scene(R"("m": )" + material, "", R"({"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "m"})");
  }
  fs::path mDir;
};

}  // namespace prism::testing_support

// The viewer script's `set sky.*` keys: each changes the scene's atmosphere; values outside the
// scene file's ranges are one line naming the key and change nothing (never clamped).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/error.h"
#include "scene/scene.h"
#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/atmosphere/viewer/sky_viewer.h"

namespace prism::viewer {
namespace {

std::string skyErrorOf(Scene& scene, const std::string& key, const std::string& value) {
  try {
    setSkyKey(scene, key, value);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SkySetKeys, ChangeTheSunAndRefuseWhatAFileWouldRefuse) {
  Scene scene;
  EXPECT_FALSE(setSkyKey(scene, "water.depth", "3"));
  EXPECT_EQ(skyErrorOf(scene, "sky.elevation", "30"), "the scene has no atmosphere");
  scene.techniques.add(std::make_unique<atmosphere::AtmosphereSection>());
  const auto* sky = scene.techniques.find<atmosphere::AtmosphereSection>();
  EXPECT_TRUE(setSkyKey(scene, "sky.elevation", "-90"));
  EXPECT_TRUE(setSkyKey(scene, "sky.azimuth", "-360"));
  EXPECT_FLOAT_EQ(sky->sunElevationDeg, -90.0f);
  EXPECT_FLOAT_EQ(sky->sunAzimuthDeg, -360.0f);
  // A user's `set sky.elevation 100` rendered as 90, and azimuth 400 was taken.
  EXPECT_NE(skyErrorOf(scene, "sky.elevation", "100").find("sky.elevation: expected a number within"), std::string::npos);
  EXPECT_NE(skyErrorOf(scene, "sky.azimuth", "400").find("sky.azimuth: expected a number within"), std::string::npos);
  EXPECT_FLOAT_EQ(sky->sunElevationDeg, -90.0f);
  EXPECT_FLOAT_EQ(sky->sunAzimuthDeg, -360.0f);
  // The model's own check names the key (it said "Ångström beta", a name the script never uses).
  EXPECT_EQ(skyErrorOf(scene, "sky.turbidity", "100").rfind("sky.turbidity: Ångström beta", 0), 0u)
      << skyErrorOf(scene, "sky.turbidity", "100");
}

}  // namespace
}  // namespace prism::viewer

// The viewer script's `set water.*` keys: a depth below the surface is refused as a scene file
// refuses it, not clamped to 0.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/error.h"
#include "scene/scene.h"
#include "techniques/underwater/viewer/water_viewer.h"
#include "techniques/underwater/water_section.h"

namespace prism::viewer {
namespace {

TEST(WaterSetKeys, RefuseANegativeDepth) {
  Scene scene;
  EXPECT_FALSE(setWaterKey(scene, "sky.elevation", "3"));
  EXPECT_THROW(setWaterKey(scene, "water.depth", "3"), Error);  // no water
  scene.techniques.add(std::make_unique<underwater::WaterSection>());
  const auto* water = scene.techniques.find<underwater::WaterSection>();
  EXPECT_TRUE(setWaterKey(scene, "water.depth", "12.5"));
  EXPECT_FLOAT_EQ(water->depthM, 12.5f);
  try {
    setWaterKey(scene, "water.depth", "-1");  // rendered as depth 0 before
    ADD_FAILURE() << "a negative depth was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("water.depth: expected a number within 0–1e+12"), std::string::npos) << e.what();
  }
  EXPECT_FLOAT_EQ(water->depthM, 12.5f);
}

}  // namespace
}  // namespace prism::viewer

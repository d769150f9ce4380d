// The viewer script's `set prt.*` keys: each changes the scene's section; bad values are one
// line naming the key and change nothing.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/scene.h"
#include "techniques/prt/prt_section.h"
#include "techniques/prt/viewer/prt_viewer.h"
#include "viewer/technique_settings.h"

namespace prism::viewer {
namespace {

std::string errorOf(Scene& scene, const std::string& key, const std::string& value) {
  try {
    setPrtKey(scene, key, value);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PrtSetKeys, ChangeTheSectionAndRefuseBadValues) {
  Scene scene;
  EXPECT_FALSE(setPrtKey(scene, "water.depth", "3"));
  EXPECT_EQ(errorOf(scene, "prt.basis", "4"), "the scene has no prt section");
  scene.techniques.add(std::make_unique<prt::PrtSection>());
  auto* s = scene.techniques.find<prt::PrtSection>();
  EXPECT_TRUE(setPrtKey(scene, "prt.basis", "4"));
  EXPECT_TRUE(setPrtKey(scene, "prt.mode", "rgb-prt"));
  EXPECT_TRUE(setPrtKey(scene, "prt.illuminant", "F11"));
  EXPECT_TRUE(setPrtKey(scene, "prt.rotation", "45"));
  EXPECT_EQ(s->basis, 4);
  EXPECT_EQ(s->mode, prt::PrtMode::RgbPrt);
  EXPECT_EQ(s->illuminant, "F11");
  EXPECT_FLOAT_EQ(s->rotationDeg, 45.0f);
  EXPECT_NE(errorOf(scene, "prt.basis", "17"), "");
  EXPECT_EQ(errorOf(scene, "prt.mode", "rgb"), "prt.mode: expected spectral, rgb-prt or reference-5nm, got 'rgb'");
  EXPECT_NE(errorOf(scene, "prt.illuminant", "F99"), "");
  // Light PRT's 380–780 nm grid does not hold (its luminance is set there: it drew black objects).
  EXPECT_EQ(errorOf(scene, "prt.illuminant", "led:830:1"),
            "led:830:1 has 0 % of its luminance on PRT's grid, 380–780 nm every 5 nm (at least 90 %: the rest, "
            "outside it or between its nodes, is lost)");
  // A line narrower than the grid's step between two nodes is lost too, and the message says so.
  EXPECT_NE(errorOf(scene, "prt.illuminant", "led:452:1").find("outside it or between its nodes"), std::string::npos);
  EXPECT_EQ(errorOf(scene, "prt.rotation", "400"), "prt.rotation: expected degrees in [-360, 360], got 400");
  EXPECT_EQ(s->basis, 4);
  EXPECT_EQ(s->illuminant, "F11");
  EXPECT_FLOAT_EQ(s->rotationDeg, 45.0f);
  // The script reaches it through the registry, like the water's and the sky's keys.
  bool registered = false;
  for (TechniqueSetKey set : techniqueSetKeys()) registered = registered || set(scene, "prt.basis", "5");
  EXPECT_TRUE(registered);
  EXPECT_EQ(s->basis, 5);
}

TEST(PrtSetKeys, MoveTheSpectralSkysSun) {
  Scene scene;
  scene.techniques.add(std::make_unique<prt::PrtSection>());
  auto* s = scene.techniques.find<prt::PrtSection>();
  EXPECT_EQ(errorOf(scene, "prt.sun-elevation", "10"),
            "prt.sun-elevation: the prt environment is not the spectral sky (\"atmosphere\")");
  s->sky = prt::PrtSky{};
  EXPECT_TRUE(setPrtKey(scene, "prt.sun-elevation", "5.5"));
  EXPECT_TRUE(setPrtKey(scene, "prt.sun-azimuth", "-120"));
  EXPECT_FLOAT_EQ(s->sky->atmosphere.sunElevationDeg, 5.5f);
  EXPECT_FLOAT_EQ(s->sky->atmosphere.sunAzimuthDeg, -120.0f);
  EXPECT_EQ(errorOf(scene, "prt.sun-elevation", "91"), "prt.sun-elevation: expected degrees in [-90, 90], got 91");
  EXPECT_FLOAT_EQ(s->sky->atmosphere.sunElevationDeg, 5.5f);
  // The sky is lit by its sun: an illuminant changed nothing (it was taken in silence).
  EXPECT_EQ(errorOf(scene, "prt.illuminant", "A"),
            "prt.illuminant: the prt environment is the spectral sky (\"atmosphere\"), lit by no illuminant");
  EXPECT_EQ(s->illuminant, "D65");
}

}  // namespace
}  // namespace prism::viewer

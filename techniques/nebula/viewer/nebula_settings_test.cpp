// The viewer script's `set nebula.*` keys: each changes the scene's section; bad values are one
// line naming the key and change nothing.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/error_test_support.h"
#include "scene/scene.h"
#include "techniques/nebula/nebula_section.h"
#include "techniques/nebula/viewer/nebula_viewer.h"
#include "viewer/technique_settings.h"

namespace prism::viewer {
namespace {

std::string nebulaKeyError(Scene& scene, const std::string& key, const std::string& value) {
  return prism::errorOf([&] { setNebulaKey(scene, key, value); });
}

TEST(NebulaSetKeys, ChangeTheSectionAndRefuseBadValues) {
  Scene scene;
  EXPECT_FALSE(setNebulaKey(scene, "prt.basis", "3"));
  EXPECT_FALSE(setNebulaKey(scene, "nebula.star.0.colour", "3"));  // not a key of the nebula's
  EXPECT_EQ(nebulaKeyError(scene, "nebula.basis", "4"), "the scene has no nebula section");
  auto section = std::make_unique<nebula::NebulaSection>();
  section->model.stars.push_back({glm::dvec3(0.5), 9000.0, 1.0});
  scene.techniques.add(std::move(section));
  auto* s = scene.techniques.find<nebula::NebulaSection>();
  EXPECT_TRUE(setNebulaKey(scene, "nebula.method", "reference"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.basis", "6"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.steps", "150"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.basis_depth", "9.5"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.filters", "cie1931"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.intensity", "300"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.extinction", "2.5"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.star.0.temperature", "30000"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.star.0.luminosity", "2"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.star.0.position", "0.1,0.2,-0.3"));
  EXPECT_EQ(s->method, nebula::Method::Reference);
  EXPECT_EQ(s->basis, 6);
  EXPECT_EQ(s->steps, 150);
  EXPECT_DOUBLE_EQ(s->renderSettings().basisMaxDepthUm, 9.5);
  EXPECT_EQ(s->model.filters, "cie1931");
  EXPECT_FLOAT_EQ(s->intensity, 300.0f);
  EXPECT_DOUBLE_EQ(s->model.extinction, 2.5);
  EXPECT_DOUBLE_EQ(s->model.stars[0].temperatureK, 30000.0);
  EXPECT_DOUBLE_EQ(s->model.stars[0].luminosity, 2.0);
  EXPECT_NEAR(s->model.stars[0].position.z, -0.3, 1e-6);

  EXPECT_EQ(nebulaKeyError(scene, "nebula.method", "spline"),
            "nebula.method: unknown nebula method 'spline' (reference, analytic, projection, light-density, "
            "pre-integration)");
  EXPECT_NE(nebulaKeyError(scene, "nebula.basis", "9"), "");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.basis_depth", "0"), "nebula.basis_depth: expected a depth in (0, 16] µm, got 0");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.filters", "jwst"), "nebula.filters: expected hubble or cie1931, got 'jwst'");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.intensity", "-1"), "nebula.intensity: expected a number ≥ 0, got -1");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.star.1.temperature", "5000"), "nebula.star.1.temperature: the nebula has 1 star(s)");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.star.0.temperature", "500"),
            "nebula.star.0.temperature: expected kelvins in [1000, 100000], got 500");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.star.0.position", "1,2"), "nebula.star.0.position: expected X,Y,Z, got 1,2");
  EXPECT_EQ(s->basis, 6);
  EXPECT_EQ(s->model.filters, "cie1931");
  EXPECT_DOUBLE_EQ(s->model.stars[0].temperatureK, 30000.0);
  // The script reaches it through the registry, like the other techniques' keys.
  bool registered = false;
  for (TechniqueSetKey set : techniqueSetKeys()) registered = registered || set(scene, "nebula.basis", "3");
  EXPECT_TRUE(registered);
  EXPECT_EQ(s->basis, 3);
}

// nebula.passband.C.shift_nm and .width move and resize channel C's passband; an edit that leaves
// nothing of it in the band, or a channel the set lacks, is refused and changes nothing.
TEST(NebulaSetKeys, MoveAndResizePassbands) {
  Scene scene;
  EXPECT_EQ(nebulaKeyError(scene, "nebula.passband.0.width", "2"), "the scene has no nebula section");
  scene.techniques.add(std::make_unique<nebula::NebulaSection>());
  auto* s = scene.techniques.find<nebula::NebulaSection>();
  EXPECT_TRUE(setNebulaKey(scene, "nebula.passband.1.shift_nm", "-20"));
  EXPECT_TRUE(setNebulaKey(scene, "nebula.passband.1.width", "2"));
  EXPECT_DOUBLE_EQ(s->model.passbands[1].shiftNm, -20.0);
  EXPECT_DOUBLE_EQ(s->model.passbands[1].widthScale, 2.0);
  EXPECT_EQ(s->model.passbands[0], nebula::PassbandEdit{});
  EXPECT_FALSE(setNebulaKey(scene, "nebula.passband.1.centre", "3"));
  EXPECT_NE(nebulaKeyError(scene, "nebula.passband.3.width", "2"), "");
  EXPECT_NE(nebulaKeyError(scene, "nebula.passband.1.width", "9").find("nebula.passband.1.width: passband F656N"),
            std::string::npos);
  EXPECT_NE(nebulaKeyError(scene, "nebula.passband.1.shift_nm", "200").find("nothing of it is left"), std::string::npos);
  EXPECT_DOUBLE_EQ(s->model.passbands[1].shiftNm, -20.0);
  EXPECT_DOUBLE_EQ(s->model.passbands[1].widthScale, 2.0);
}

// nebula.ionisation on|off, and its front's radius and width (which turn the zones on); a value out
// of range is refused and changes nothing.
TEST(NebulaSetKeys, IonisationZones) {
  Scene scene;
  scene.techniques.add(std::make_unique<nebula::NebulaSection>());
  auto* s = scene.techniques.find<nebula::NebulaSection>();
  EXPECT_TRUE(setNebulaKey(scene, "nebula.ionisation.front_radius", "0.5"));
  ASSERT_TRUE(s->model.ionisation.has_value());
  EXPECT_DOUBLE_EQ(s->model.ionisation->frontRadius, 0.5);
  EXPECT_TRUE(setNebulaKey(scene, "nebula.ionisation.front_width", "0.2"));
  EXPECT_EQ(nebulaKeyError(scene, "nebula.ionisation.front_width", "0.7"),
            "nebula.ionisation.front_width: expected a number in (0, 0.5], got 0.7");
  EXPECT_EQ(nebulaKeyError(scene, "nebula.ionisation", "maybe"), "nebula.ionisation: expected on or off, got 'maybe'");
  EXPECT_EQ(s->model.ionisation->frontWidth, 0.2);
  EXPECT_TRUE(setNebulaKey(scene, "nebula.ionisation", "off"));
  EXPECT_FALSE(s->model.ionisation.has_value());
  EXPECT_TRUE(setNebulaKey(scene, "nebula.ionisation", "on"));
  EXPECT_EQ(s->model.ionisation, nebula::IonisationModel{});
}

// nebula.light_surfaces on|off: whether the stars light the scene's surfaces.
TEST(NebulaSetKeys, StarsLightSurfacesOrNot) {
  Scene scene;
  scene.techniques.add(std::make_unique<nebula::NebulaSection>());
  auto* s = scene.techniques.find<nebula::NebulaSection>();
  EXPECT_TRUE(s->lightSurfaces);
  EXPECT_TRUE(setNebulaKey(scene, "nebula.light_surfaces", "off"));
  EXPECT_FALSE(s->lightSurfaces);
  EXPECT_EQ(nebulaKeyError(scene, "nebula.light_surfaces", "1"), "nebula.light_surfaces: expected on or off, got '1'");
  EXPECT_FALSE(s->lightSurfaces);
  EXPECT_TRUE(setNebulaKey(scene, "nebula.light_surfaces", "on"));
  EXPECT_TRUE(s->lightSurfaces);
}

}  // namespace
}  // namespace prism::viewer

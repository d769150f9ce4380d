#include "viewer/scene_settings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "scene/conductors.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::viewer {
namespace {

Scene twoLights() {
  Scene scene;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0.0f, -1.0f, 0.0f};
  Light lamp;
  lamp.type = LightType::Point;
  lamp.position = {0.0f, 2.0f, 0.0f};
  lamp.castsShadows = false;
  scene.lights = {sun, lamp};
  Material floor;
  floor.name = "floor";
  scene.materials = {floor};
  return scene;
}

std::string error(Scene& scene, const std::string& key, const std::string& value) {
  try {
    applySceneSetting(scene, key, value);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SceneSettings, MovesAPointLightAndTurnsItsShadowsOnAndOff) {
  Scene scene = twoLights();
  EXPECT_TRUE(applySceneSetting(scene, "light.1.position", "1.5,2,-3"));
  EXPECT_EQ(scene.lights[1].position, glm::vec3(1.5f, 2.0f, -3.0f));
  EXPECT_TRUE(applySceneSetting(scene, "light.1.shadows", "on"));
  EXPECT_TRUE(scene.lights[1].castsShadows);
  EXPECT_TRUE(applySceneSetting(scene, "light.1.shadows", "off"));
  EXPECT_FALSE(scene.lights[1].castsShadows);
  EXPECT_TRUE(applySceneSetting(scene, "light.0.intensity", "250"));
  EXPECT_EQ(scene.lights[0].intensity, 250.0f);
  EXPECT_TRUE(applySceneSetting(scene, "material.floor.roughness", "0.3"));
  EXPECT_EQ(scene.materials[0].roughness, 0.3f);
}

// An emitter's luminance, its spectrum's shape kept; a material that emits nothing is refused.
TEST(SceneSettings, AnEmittersLuminanceKeepsItsSpectrum) {
  Scene scene = twoLights();
  EXPECT_EQ(error(scene, "material.floor.emission-luminance", "10"),
            "material.floor.emission-luminance: floor emits no light (what it emits is the scene file's or its glTF's)");
  const Spectrum a = illuminant("A");
  scene.materials[0].emission = Emission{a * (1.0 / luminousIntegral(a)), 5.0f};
  EXPECT_TRUE(applySceneSetting(scene, "material.floor.emission-luminance", "80"));
  EXPECT_NEAR(luminousIntegral(scene.materials[0].emission->radiance()), 80.0, 80.0 * 1e-6);
  EXPECT_NEAR(scene.materials[0].emission->spd.at(450.0) / scene.materials[0].emission->spd.at(650.0),
              a.at(450.0) / a.at(650.0), 1e-12);
  EXPECT_EQ(error(scene, "material.floor.emission-luminance", "0"),
            "material.floor.emission-luminance: expected a luminance above 0, got \"0\"");
  EXPECT_EQ(scene.materials[0].emission->luminance, 80.0f);  // nothing half-set
  // glTF's emission: the cd/m² of its emissive white.
  scene.materials[0].emission.reset();
  scene.materials[0].emissiveFactor = glm::vec3(1.0f, 0.5f, 0.2f);
  scene.materials[0].emissiveLuminance = 5.0f;
  EXPECT_TRUE(applySceneSetting(scene, "material.floor.emission-luminance", "40"));
  EXPECT_EQ(scene.materials[0].emissiveLuminance, 40.0f);
}

TEST(SceneSettings, ALightsSpdComesFromACsvFileAsThePanelsDoes) {
  // A script's light.N.spd took names alone: "red.csv" was an unknown illuminant.
  const std::filesystem::path csv = std::filesystem::path(::testing::TempDir()) / "red_lamp.csv";
  std::ofstream(csv) << "wavelength,value\n600,0\n650,1\n700,0\n";
  Scene scene = twoLights();
  EXPECT_TRUE(applySceneSetting(scene, "light.1.spd", csv.string()));
  EXPECT_EQ(scene.lights[1].spdLabel, "csv:" + csv.string());
  EXPECT_GT(scene.lights[1].spd.at(650.0), 0.0);
  EXPECT_EQ(scene.lights[1].spd.at(550.0), 0.0);
  EXPECT_NE(error(scene, "light.1.spd", (std::filesystem::path(::testing::TempDir()) / "none.csv").string()), "");
}

TEST(SceneSettings, OtherKeysAreNotItsOwn) {
  Scene scene = twoLights();
  EXPECT_FALSE(applySceneSetting(scene, "mode", "rgb"));
  EXPECT_FALSE(applySceneSetting(scene, "sky.elevation", "30"));
  EXPECT_FALSE(applySceneSetting(scene, "light.1", "on"));
}

TEST(SceneSettings, BadValuesAreOneLineErrorsNamingTheKey) {
  Scene scene = twoLights();
  EXPECT_EQ(error(scene, "light.0.position", "1,2,3"), "light.0.position: light 0 is directional: it has no position");
  EXPECT_EQ(error(scene, "light.1.shadows", "yes"), "light.1.shadows: expected on or off, got \"yes\"");
  EXPECT_NE(error(scene, "light.1.position", "1,2"), "");
  EXPECT_NE(error(scene, "light.7.intensity", "1"), "");
  EXPECT_NE(error(scene, "light.1.colour", "1"), "");
  EXPECT_NE(error(scene, "material.wood.roughness", "1"), "");
  // Out of range is refused, never clamped: a script says what it means.
  EXPECT_EQ(error(scene, "light.0.intensity", "-3"), "light.0.intensity: expected a number within 0–1e+12, got \"-3\"");
  EXPECT_EQ(error(scene, "material.floor.roughness", "1.5"),
            "material.floor.roughness: expected a number within 0–1, got \"1.5\"");
  EXPECT_EQ(error(scene, "material.floor.base-colour", "0.5,2,0"),
            "material.floor.base-colour: expected R,G,B within 0–1, got \"0.5,2,0\"");
  EXPECT_EQ(scene.lights[1].position, glm::vec3(0.0f, 2.0f, 0.0f));  // nothing half-set
  // A lambertian material takes no metal, as the scene loader says too (it rendered black).
  scene.materials[0].lambertian = true;
  EXPECT_EQ(error(scene, "material.floor.metallic", "0.5"),
            "material.floor.metallic: floor is lambertian, which diffuses all of the light: metallic must be 0");
  EXPECT_EQ(error(scene, "material.floor.metallic", "0"), "");
  scene.materials[0].lambertian = false;
  // A conductor's colour and metalness are its n and k, as the scene loader says too.
  scene.materials[0].conductor = conductorIor("Au");
  EXPECT_EQ(error(scene, "material.floor.metallic", "0"),
            "material.floor.metallic: floor is a conductor, whose colour and metalness are its measured n and k");
  EXPECT_NE(error(scene, "material.floor.base-colour", "1,0,0"), "");
  EXPECT_EQ(error(scene, "material.floor.roughness", "0.3"), "");
}

}  // namespace
}  // namespace prism::viewer

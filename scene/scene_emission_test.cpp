#include "scene/scene_emission.h"

#include <gtest/gtest.h>

#include <numbers>

#include "scene/scene_loader.h"
#include "spectral/illuminant.h"
#include "spectral/rgb_intent.h"
#include "spectral/table_test_support.h"

namespace prism {
namespace {

Light light(LightType type, const char* spd, float intensity) {
  Light l;
  l.type = type;
  l.spd = normalisedLightSpectrum(illuminant(spd));
  l.intensity = intensity;
  return l;
}

TEST(SceneEmission, SumsTheLightsByIntensityAndTheBackgroundAsTheIlluminanceItGives) {
  // Every SPD is photometrically normalised, so the emission's luminous integral is the sum of
  // the intensities (lux, candela) plus π × the background's luminance (cd/m²).
  Scene scene;
  scene.lights.push_back(light(LightType::Directional, "D65", 1000.0f));
  scene.lights.push_back(light(LightType::Point, "A", 50.0f));
  EXPECT_NEAR(luminousIntegral(sceneEmission(scene, colourSpace("srgb"), cachedTestTable())) / 1050.0, 1.0, 1e-9);
  Spectrum lightsOnly = sceneEmission(scene, colourSpace("srgb"), cachedTestTable());
  EXPECT_DOUBLE_EQ(lightsOnly.at(450.0), 1000.0 * scene.lights[0].spd.at(450.0) + 50.0 * scene.lights[1].spd.at(450.0));
  scene.background = glm::vec3(1.0f);
  scene.backgroundLuminance = 100.0f;
  // The white background is the colour space's white (D65) through the table's fit of (1, 1, 1).
  EXPECT_NEAR(luminousIntegral(sceneEmission(scene, colourSpace("srgb"), cachedTestTable())) / (1050.0 + 100.0 * std::numbers::pi), 1.0, 1e-3);
}

// An emitting material is weighed as a background of its radiance, once a mesh shows it; the fit
// takes its spectrum as one more light, whatever its luminance.
TEST(SceneEmission, AnEmitterCountsWhereAMeshShowsIt) {
  Scene scene;
  scene.lights.push_back(light(LightType::Directional, "D65", 1000.0f));
  Material tube;
  tube.emission = Emission{normalisedLightSpectrum(illuminant("F11")), 40.0f};
  scene.materials.push_back(tube);
  const SamplingSettings settings;
  EXPECT_NEAR(luminousIntegral(sceneEmission(scene, colourSpace("srgb"), cachedTestTable())), 1000.0, 1e-6);
  EXPECT_EQ(sceneWavelengthFitProblem(settings, scene, colourSpace("srgb"), cachedTestTable()).lights.size(), 1u);
  scene.meshes.emplace_back();  // material 0
  EXPECT_NEAR(luminousIntegral(sceneEmission(scene, colourSpace("srgb"), cachedTestTable())) /
                  (1000.0 + 40.0 * std::numbers::pi), 1.0, 1e-9);
  const WavelengthFitProblem problem = sceneWavelengthFitProblem(settings, scene, colourSpace("srgb"), cachedTestTable());
  ASSERT_EQ(problem.lights.size(), 2u);
  EXPECT_NEAR(luminousIntegral(problem.lights[1]), 1.0, 1e-9);
  scene.materials[0].emission->luminance = 400.0f;
  EXPECT_EQ(sceneWavelengthFitProblem(settings, scene, colourSpace("srgb"), cachedTestTable()).lights[1], problem.lights[1]);
}

// glTF's emission counts as its colour upsampled as a light's at π·L (its factor's, or under a
// texture, which may take it to any colour within the factor's channels, the white at the
// factor's largest); the fit takes that spectrum at a luminance of its own, so that an edit of
// the luminance finds the cached fit.
TEST(SceneEmission, GltfEmissionCountsAsItsColourOrUnderATextureAsWhite) {
  Scene scene;
  Material panel;
  panel.emissiveFactor = glm::vec3(0.2f, 0.5f, 1.0f);
  panel.emissiveLuminance = 30.0f;
  scene.materials.push_back(panel);
  scene.meshes.emplace_back();  // material 0
  const RgbColourSpace& srgb = colourSpace("srgb");
  const SamplingSettings settings;
  const Spectrum flat = RgbIlluminantSpectrum(cachedTestTable(), srgb, panel.emissiveFactor, 30.0).toDense();
  EXPECT_TRUE(sceneEmission(scene, srgb, cachedTestTable()) == std::numbers::pi * flat);
  const WavelengthFitProblem problem = sceneWavelengthFitProblem(settings, scene, srgb, cachedTestTable());
  ASSERT_EQ(problem.lights.size(), 1u);
  scene.materials[0].emissiveLuminance = 300.0f;
  EXPECT_TRUE(sceneWavelengthFitProblem(settings, scene, srgb, cachedTestTable()).lights[0] == problem.lights[0]);
  scene.materials[0].emissiveTexture = 0;
  const Spectrum white = RgbIlluminantSpectrum(cachedTestTable(), srgb, glm::vec3(1.0f), 300.0).toDense();
  EXPECT_TRUE(sceneEmission(scene, srgb, cachedTestTable()) == std::numbers::pi * white);
  scene.materials[0].emissiveLuminance = 0.0f;  // dark: nothing to count
  EXPECT_TRUE(sceneEmission(scene, srgb, cachedTestTable()) == Spectrum());
}

// The Optimised strategy's training set: each distinct light SPD once (two D65 lights are one),
// the standard reflectances plus one per material; equal energy when nothing emits.
TEST(SceneEmission, TheWavelengthFitTrainsOnTheDistinctLightsAndTheScenesSurfaces) {
  Scene scene;
  scene.lights.push_back(light(LightType::Directional, "D65", 1000.0f));
  scene.lights.push_back(light(LightType::Point, "D65", 20.0f));
  scene.lights.push_back(light(LightType::Point, "F11", 50.0f));
  scene.materials.resize(2);
  const SamplingSettings settings{8, 380, 780, SamplingStrategy::Optimised};
  const WavelengthFitProblem problem = sceneWavelengthFitProblem(settings, scene, colourSpace("srgb"), cachedTestTable());
  ASSERT_EQ(problem.lights.size(), 2u);
  EXPECT_TRUE(problem.lights[0] == scene.lights[0].spd);
  EXPECT_TRUE(problem.lights[1] == scene.lights[2].spd);
  EXPECT_EQ(problem.reflectances.size(), standardTrainingReflectances(cachedTestTable()).size() + 2);
  EXPECT_EQ(problem.count, 8);
  EXPECT_EQ(problem.minNm, 380.0);
  scene.lights.clear();
  const WavelengthFitProblem dark = sceneWavelengthFitProblem(settings, scene, colourSpace("srgb"), cachedTestTable());
  ASSERT_EQ(dark.lights.size(), 1u);
  EXPECT_TRUE(dark.lights[0] == Spectrum::constant(1.0));
}

TEST(SceneEmission, OnlyTheLightsStrategyFollowsIt) {
  Scene scene;
  scene.lights.push_back(light(LightType::Directional, "led:450:20", 1000.0f));
  const Observer& cie = observer("cie1931");
  WavelengthSampler lights = sceneWavelengthSampler({16, 360, 830, SamplingStrategy::Lights}, cie, scene, colourSpace("srgb"), cachedTestTable());
  WavelengthSampler importance =
      sceneWavelengthSampler({16, 360, 830, SamplingStrategy::Importance}, cie, scene, colourSpace("srgb"), cachedTestTable());
  ASSERT_NE(lights.pdf(), nullptr);
  ASSERT_NE(importance.pdf(), nullptr);
  EXPECT_GT(lights.pdf()->density(450.5), 4.0 * importance.pdf()->density(450.5));
  EXPECT_EQ(sceneWavelengthSampler({16, 360, 830, SamplingStrategy::Rotated}, cie, scene, colourSpace("srgb"), cachedTestTable()).pdf(), nullptr);
}

}  // namespace
}  // namespace prism

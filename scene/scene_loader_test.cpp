#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <limits>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "spectral/colour_space.h"
#include "core/error.h"
#include "core/error_test_support.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "scene/scene_folder_test_support.h"

namespace prism {
namespace {

using namespace testing_support;

TEST(SceneLoader, ValidSceneLoadsWithExpectedCountsAndValues) {
  Scene s = loadScene(kFixtures / "basic.json");
  EXPECT_EQ(s.file, kFixtures / "basic.json");
  EXPECT_EQ(s.colourSpace, "srgb");
  EXPECT_EQ(s.camera.position, glm::vec3(0.0f, 1.5f, 6.0f));
  EXPECT_EQ(s.camera.target, glm::vec3(0.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(s.camera.verticalFovDeg, 40.0f);
  EXPECT_FLOAT_EQ(s.camera.nearPlane, 0.1f);
  EXPECT_FLOAT_EQ(s.camera.farPlane, 100.0f);
  EXPECT_FLOAT_EQ(s.camera.ev100, 12.0f);

  ASSERT_EQ(s.lights.size(), 5u);
  EXPECT_EQ(s.lights[0].type, LightType::Directional);
  EXPECT_EQ(s.lights[0].direction, glm::vec3(0.0f, -1.0f, 0.0f));  // normalised on load
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 10000.0f);
  EXPECT_TRUE(s.lights[0].castsShadows);
  EXPECT_EQ(s.lights[0].spdLabel, "D65");
  EXPECT_EQ(s.lights[1].type, LightType::Point);
  EXPECT_EQ(s.lights[1].position, glm::vec3(1.0f, 3.0f, 1.0f));
  EXPECT_FALSE(s.lights[1].castsShadows);
  EXPECT_EQ(s.lights[1].spdLabel, "blackbody:2700");
  EXPECT_EQ(s.lights[2].type, LightType::Spot);
  EXPECT_FLOAT_EQ(s.lights[2].innerConeDeg, 20.0f);
  EXPECT_FLOAT_EQ(s.lights[2].outerConeDeg, 30.0f);
  EXPECT_NEAR(glm::length(s.lights[2].direction), 1.0f, 1e-6f);
  EXPECT_EQ(s.lights[2].spdLabel, "csv:lamp.csv");
  EXPECT_EQ(s.lights[3].spdLabel, "led:450:20");
  EXPECT_EQ(s.lights[4].spdLabel, "rgb:[1.0,0.5,0.25]");

  // Five scene materials (sorted by name), then quad.gltf's "tiles" and triangle.glb has none
  // of its own (it is overridden), but quad.gltf's second primitive takes the glTF default.
  ASSERT_EQ(s.materials.size(), 7u);
  EXPECT_EQ(s.materials[0].name, "gold");
  ASSERT_TRUE(s.materials[0].conductor.has_value());
  EXPECT_EQ(s.materials[0].conductor->name, "Au");
  EXPECT_EQ(s.materials[1].name, "grey_srgb");
  EXPECT_EQ(s.materials[2].name, "paint");
  ASSERT_TRUE(s.materials[2].reflectance.has_value());
  EXPECT_DOUBLE_EQ(s.materials[2].reflectance->at(600.0), 0.6);
  EXPECT_DOUBLE_EQ(s.materials[2].reflectance->at(380.0), 0.05);  // clamped below 400 nm
  EXPECT_EQ(s.materials[3].name, "red");
  EXPECT_EQ(s.materials[3].baseColour, glm::vec3(0.8f, 0.1f, 0.1f));
  EXPECT_FLOAT_EQ(s.materials[3].roughness, 0.4f);
  EXPECT_FLOAT_EQ(s.materials[3].metallic, 0.0f);
  EXPECT_EQ(s.materials[4].name, "tiled");
  EXPECT_EQ(s.materials[5].name, "quad.gltf/tiles");
  EXPECT_EQ(s.materials[6].name, "quad.gltf/default");

  // sphere, plane, box, quad.gltf's two primitives, triangle.glb.
  ASSERT_EQ(s.meshes.size(), 6u);
  EXPECT_EQ(s.meshes[0].name, "ball");
  EXPECT_EQ(s.meshes[0].material, 3);
  EXPECT_EQ(s.meshes[1].name, "/objects/1");
  EXPECT_EQ(s.meshes[1].material, 1);
  EXPECT_EQ(s.meshes[2].material, 0);
  EXPECT_EQ(s.meshes[3].material, 5);
  EXPECT_EQ(s.meshes[4].material, 6);
  EXPECT_EQ(s.meshes[5].material, 2);  // the object's material override
  EXPECT_EQ(s.meshes[2].vertices.size(), 24u);
  EXPECT_EQ(s.meshes[2].indices.size(), 36u);

  // checker.png twice from the scene (sRGB and linear: not decoded twice per use), and
  // quad.gltf's image twice (base colour sRGB, normal map linear).
  ASSERT_EQ(s.textures.size(), 4u);
  EXPECT_EQ(s.materials[4].baseColourTexture, 0);
  EXPECT_EQ(s.materials[4].normalTexture, 1);
  EXPECT_TRUE(s.textures[0].srgb);
  EXPECT_FALSE(s.textures[1].srgb);
  EXPECT_EQ(s.textures[0].width, 2);
  EXPECT_EQ(s.textures[0].rgba.size(), 16u);

  EXPECT_EQ(s.background, glm::vec3(0.5f, 0.7f, 1.0f));
  EXPECT_FLOAT_EQ(s.backgroundLuminance, 2000.0f);

  Bounds b = sceneBounds(s);
  EXPECT_FLOAT_EQ(b.min.x, -5.0f);  // the plane
  EXPECT_FLOAT_EQ(b.max.z, 14.0f);  // quad.gltf's (−0.5, 0.5, 0) → (1, 3, 4), moved 10 along z
}

TEST(SceneLoader, SrgbBaseColourIsDecodedExactly) {
  Scene s = loadScene(kFixtures / "basic.json");
  // IEC 61966-2-1: ((0.5 + 0.055) / 1.055)^2.4 = 0.214041.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.materials[1].baseColour[c], 0.214041f, 1e-5f);
}

TEST(SceneLoader, EveryLightIsPhotometricallyNormalised) {
  Scene s = loadScene(kFixtures / "basic.json");
  const Observer& cie = observer("cie1931");
  for (const Light& l : s.lights) {
    // 683 lm/W · ∫ S ȳ dλ = 1: only rounding of the 471-term trapezoid sum remains.
    EXPECT_NEAR(683.0 * cie.integrate(l.spd)[1], 1.0, 1e-6) << l.spdLabel;
    EXPECT_NEAR(luminousIntegral(l.spd), 1.0, 1e-6) << l.spdLabel;
  }
}

TEST(SceneLoader, RgbLightHasTheColoursChromaticity) {
  Scene s = loadScene(kFixtures / "basic.json");
  const Light& l = s.lights[4];
  Eigen::Vector3d xyz = observer("cie1931").integrate(l.spd);
  Eigen::Vector3d rgb = colourSpace("srgb").xyzToRgb * xyz;
  // The sigmoid fit of (1, 0.5, 0.25)/2 is within a fraction of a ΔE76: 2 % of each ratio.
  EXPECT_NEAR(rgb[1] / rgb[0], 0.5, 0.01);
  EXPECT_NEAR(rgb[2] / rgb[0], 0.25, 0.005);
}

TEST(SceneLoader, OverridesApplyBeforeValidation) {
  Scene s = loadScene(kFixtures / "basic.json",
                      {"camera.ev100=2", "lights.0.intensity=5", "materials.red.roughness=0.3",
                       "lights.1.spd=blackbody:3000", "materials.red.metallic=1",
                       "camera.position=[0, 2, 8]"});
  EXPECT_EQ(s.camera.position, glm::vec3(0.0f, 2.0f, 8.0f));
  EXPECT_FLOAT_EQ(s.camera.ev100, 2.0f);
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 5.0f);
  EXPECT_FLOAT_EQ(s.materials[3].roughness, 0.3f);
  EXPECT_FLOAT_EQ(s.materials[3].metallic, 1.0f);  // a key the file did not have
  EXPECT_EQ(s.lights[1].spdLabel, "blackbody:3000");
}

// An empty name is said once at its key: the name's own error was caught by the lookup's and
// located again ("…/colour_space: …/colour_space: expected a non-empty string").
TEST(SceneLoader, AnEmptyNameIsSaidOnceAtItsKey) {
  fs::path f = kFixtures / "basic.json";
  EXPECT_EQ(errorOf([&] { loadScene(f, {"colour_space=\"\""}); }),
            f.string() + ": /colour_space (set on the command line): expected a non-empty string, got \"\"");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"materials.gold.conductor=\"\""}); }),
            f.string() + ": /materials/gold/conductor (set on the command line): expected a non-empty string, got \"\"");
}

TEST(SceneLoader, OverrideOfAnUnknownPathFails) {
  fs::path f = kFixtures / "basic.json";
  EXPECT_EQ(errorOf([&] { loadScene(f, {"lights.9.intensity=5"}); }),
            f.string() + ": /lights/9: --set lights.9.intensity=5: no element 9 (the array has 5)");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"materials.blue.roughness=0.3"}); }),
            f.string() + ": /materials/blue: --set materials.blue.roughness=0.3: no such key "
                         "(here: gold, grey_srgb, paint, red, tiled)");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"camera.evv100=2"}); }), f.string() + ": /camera/evv100 (set on the command line): unknown key (allowed: "));
  EXPECT_EQ(errorOf([&] { loadScene(f, {"camera.ev100.x=2"}); }),
            f.string() + ": /camera/ev100: --set camera.ev100.x=2: cannot look up 'x' in 12");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"camera"}); }),
            f.string() + ": /: --set camera: expected PATH=VALUE, e.g. camera.ev100=2");
  // A value that is valid JSON but the wrong type is caught by validation, and the message says
  // where it came from: the file has no "bright" to find.
  EXPECT_EQ(errorOf([&] { loadScene(f, {"lights.0.intensity=bright"}); }),
            f.string() + ": /lights/0/intensity (set on the command line): expected a number in (0, 1e+12], got \"bright\"");
}

TEST_F(SceneFolder, MalformedJsonReportsLineAndColumn) {
  fs::path f = write("scene.json", "{\n  \"camera\": {,\n}\n");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }), f.string() + ":2:14: malformed JSON: syntax error"));
  fs::path g = write("truncated.json", "{\"camera\": {}");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(g); }), g.string() + ":1:14: malformed JSON: "));
}

TEST_F(SceneFolder, DuplicateKeysAreErrors) {
  fs::path f = sceneWithMaterial(R"({"roughness": 0.2, "roughness": 0.9})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /materials/m/roughness: duplicate key");
}

TEST_F(SceneFolder, UnknownKeyListsTheAllowedOnes) {
  fs::path f = sceneWithMaterial(R"({"base_color": [1, 0, 0]})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/base_color: unknown key (allowed: base_colour, base_colour_srgb, "
                         "metallic, roughness, lambertian, reflectance, conductor, base_colour_texture, "
                         "metallic_roughness_texture, normal_texture, spectral_texture, emission)");
}

// An emitting material: a light's spectrum, normalised, times the luminance the file gives.
TEST_F(SceneFolder, AnEmissionIsItsSpectrumAtItsLuminance) {
  fs::path f = sceneWithMaterial(R"({"emission": {"spd": "blackbody:2700", "luminance": 250}})");
  const Scene scene = loadScene(f);
  ASSERT_TRUE(scene.materials.at(0).emission);
  EXPECT_EQ(scene.materials.at(0).emission->luminance, 250.0f);
  EXPECT_NEAR(luminousIntegral(scene.materials.at(0).emission->radiance()), 250.0, 250.0 * 1e-12);
  Spectrum planck = illuminant("blackbody:2700");
  const Spectrum& e = scene.materials.at(0).emission->spd;
  EXPECT_NEAR(e.at(500.0) / e.at(600.0), planck.at(500.0) / planck.at(600.0), 1e-12);
}

TEST_F(SceneFolder, WrongTypesAndRangesNameThePlace) {
  fs::path f = sceneWithLight(R"({"type": "point", "position": [0, 1, 0], "spd": "D65", "intensity": "bright"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/intensity: expected a number in (0, 1e+12], got \"bright\"");
  f = sceneWithLight(R"({"type": "point", "position": [0, 1], "spd": "D65", "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/position: expected an array of 3 numbers, got [0,1]");
  f = sceneWithLight(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "inner_cone_deg": 50,
                         "outer_cone_deg": 40, "spd": "D65", "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/inner_cone_deg: inner_cone_deg (50.0) exceeds outer_cone_deg (40.0)");
  f = sceneWithLight(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "outer_cone_deg": 90,
                         "spd": "D65", "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/outer_cone_deg: expected a number in (0, 90), got 90");
  f = sceneWithLight(R"({"type": "directional", "direction": [0, 0, 0], "spd": "D65", "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /lights/0/direction: expected a non-zero direction");
  f = sceneWithLight(R"({"type": "area", "spd": "D65", "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/type: unknown light type 'area' (directional, point, spot)");
  f = sceneWithLight(R"({"type": "point", "position": [0, 1, 0], "spd": "D66", "intensity": 1})");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
              f.string() + ": /lights/0/spd: unknown illuminant 'D66'"));
  f = sceneWithLight(R"({"type": "point", "position": [0, 1, 0], "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /lights/0: missing required key 'spd'");
  f = sceneWithMaterial(R"({"roughness": 1.5})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/roughness: expected a number in [0, 1], got 1.5");
  f = sceneWithMaterial(R"({"metallic": true})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/metallic: expected a number in [0, 1], got true");
}

// Numbers the float pipeline cannot carry, and documents too deep to walk, are refused where they
// are, before anything overflows or recurses.
TEST_F(SceneFolder, NumbersBeyondFloatsReachAndDeepNestingAreRefused) {
  fs::path f = sceneWithLight(R"({"type": "point", "position": [0, 1, 0], "spd": "D65", "intensity": 1e39})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/intensity: expected a number in (0, 1e+12], got 1e+39");
  f = sceneWithLight(R"({"type": "point", "position": [0, 1e39, 0], "spd": "D65", "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/position/1: expected a number in [-1e+12, 1e+12], got 1e+39");
  f = sceneWithLight("");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"camera.position=[1e39, 0, 0]"}); }),
            f.string() + ": /camera/position/0 (set on the command line): expected a number in [-1e+12, 1e+12], got 1e+39");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"camera.fov_deg=1e-30"}); }),
            f.string() + ": /camera/fov_deg (set on the command line): expected a number in [0.001, 180), got 1e-30");
  // A near plane so close that depth cannot place surfaces (far 200 / 1e-5: the image went black).
  EXPECT_EQ(errorOf([&] { loadScene(f, {"camera.near=1e-5"}); }),
            f.string() + ": /camera/near (set on the command line): far / near = 2e+07 is past 200000, where depth loses the precision lighting "
                         "needs: raise near or lower far");
  EXPECT_NO_THROW(loadScene(f, {"camera.near=0.001"}));  // 200 000
  EXPECT_EQ(errorOf([&] { loadScene(f, {"background={\"colour\": [1, 1, 1], \"luminance\": 1e39}"}); }),
            f.string() + ": /background/luminance (set on the command line): expected a number in [0, 1e+12], got 1e+39");

  // 100 000 nested arrays: refused at the 64th level, naming where (at most 80 characters of it).
  std::string deep = std::string(100000, '[') + std::string(100000, ']');
  fs::path d = write("deep.json", R"({"$schema": )" + deep + "}");
  const std::string nested = errorOf([&] { loadScene(d); });
  EXPECT_TRUE(startsWith(nested, d.string() + ": /$schema/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0"));
  EXPECT_TRUE(contains(nested, "/0/...: nested deeper than 64 levels"));
  EXPECT_LT(nested.size(), d.string().size() + 120);
  const std::string error = errorOf([&] { loadScene(f, {"camera.ev100=" + deep}); });
  EXPECT_TRUE(startsWith(error, f.string() + ": /: --set camera.ev100=[[[[[[[[[["));
  EXPECT_TRUE(contains(error, "...: the value nests deeper than 64 levels"));
  EXPECT_LT(error.size(), 300u);
}

TEST_F(SceneFolder, ObjectsMustNameAKnownMaterialAndOneShape) {
  fs::path f = scene(R"("a": {}, "b": {})", "", R"({"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "c"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /objects/0/material: unknown material 'c' (materials: a, b)");
  f = scene(R"("a": {})", "", R"({"sphere": {"centre": [0, 0, 0], "radius": 1}, "box": {}, "material": "a"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /objects/0: expected only one of the keys sphere, plane, box, heightfield, gltf, got sphere, box");
  f = scene(R"("a": {})", "", R"({"sphere": {"centre": [0, 0, 0], "radius": 0}, "material": "a"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /objects/0/sphere/radius: expected a number in (0, 1e+12], got 0");
}

TEST_F(SceneFolder, MissingTextureNamesTheResolvedPath) {
  fs::path f = sceneWithMaterial(R"({"base_colour_texture": "textures/missing.png"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/base_colour_texture: file not found: " + (mDir / "textures/missing.png").string());
}

TEST_F(SceneFolder, HdrAndExrTexturesAreRefused) {
  write("sky.exr", std::string("\x76\x2f\x31\x01", 4) + "rest of an OpenEXR file");
  fs::path f = sceneWithMaterial(R"({"base_colour_texture": "sky.exr"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/base_colour_texture: " + (mDir / "sky.exr").string() +
                ": OpenEXR images are not supported (only PNG and JPEG)");
  write("sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n");
  f = sceneWithMaterial(R"({"normal_texture": "sky.hdr"})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "sky.hdr: Radiance HDR images are not supported"));
}

TEST_F(SceneFolder, FilesMustStayInsideTheSceneFolder) {
  write("../outside.png", "x");
  fs::path f = sceneWithMaterial(R"({"base_colour_texture": "../outside.png"})");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
              f.string() + ": /materials/m/base_colour_texture: '..' is not allowed in '../outside.png'"));
  f = sceneWithMaterial(R"({"base_colour_texture": "/etc/hostname"})");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
              f.string() + ": /materials/m/base_colour_texture: absolute path '/etc/hostname' is not allowed"));
  fs::create_directory_symlink(mDir.parent_path(), mDir / "escape");
  f = sceneWithMaterial(R"({"base_colour_texture": "escape/outside.png"})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), ": /materials/m/base_colour_texture: 'escape/outside.png' resolves to "));
}

TEST_F(SceneFolder, UnknownConductorListsTheKnownOnes) {
  fs::path f = sceneWithMaterial(R"({"conductor": "Pt"})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/conductor: unknown conductor 'Pt' (known: Ag, Al, Au, Cu, CuZn, MgO, TiO2)");
}

// A conductor's colour and metalness are its n and k: a base colour or metallic beside it was
// ignored in every mode without a word.
TEST_F(SceneFolder, AConductorTakesNoColourOfItsOwn) {
  fs::path f = sceneWithMaterial(R"({"conductor": "Au", "base_colour": [1, 0, 0]})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/base_colour: a conductor's colour and metalness are its measured n and k: give "
                         "base_colour or conductor, not both");
  f = sceneWithMaterial(R"({"conductor": "Cu", "metallic": 0})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), ": /materials/m/metallic: a conductor's colour"));
}

TEST_F(SceneFolder, SpdCsvWithBadDataNamesFileLineAndColumn) {
  fs::path csv = write("lamp.csv", "wavelength_nm,value\n400,1\n500,abc\n");
  fs::path f = sceneWithLight(R"({"type": "point", "position": [0, 1, 0], "spd": {"csv": "lamp.csv"}, "intensity": 1})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/spd/csv: " + csv.string() + ":3:2: expected a number in column 'value', found 'abc'");
  write("lamp.csv", "wavelength_nm,value\n400,1\n500,-1\n");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /lights/0/spd/csv: " + csv.string() + ":3:2: value -1 is negative");
  write("lamp.csv", "wavelength_nm,value\n850,1\n900,2\n");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /lights/0/spd/csv: " + csv.string() +
                                                ": its wavelengths (850–900 nm) lie outside 360–830 nm, the range Prism renders");
  write("lamp.csv", "wavelength_nm,value\n400,0\n500,0\n");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /lights/0/spd/csv: " + csv.string() +
                ": the lamp has no luminous power (683 lm/W · ∫ S ȳ dλ = 0 over 360–830 nm)");
  fs::path paint = write("paint.csv", "wavelength_nm,reflectance\n400,0.5\n500,1.5\n");
  f = sceneWithMaterial(R"({"reflectance": {"csv": "paint.csv"}})");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/reflectance/csv: " + paint.string() + ":3:2: value 1.5 is outside [0, 1]");
}

TEST_F(SceneFolder, GltfUrisMustStayInsideTheSceneFolder) {
  write("../outside.bin", std::string(12, '\0'));
  std::string gltf = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12, "uri": "URI"}]})";
  auto withUri = [&](const std::string& uri) {
    std::string text = gltf;
    text.replace(text.find("URI"), 3, uri);
    write("models/m.gltf", text);
    return scene(R"("a": {})", "", R"({"gltf": "models/m.gltf"})");
  };
  fs::path model = mDir / "models/m.gltf";
  fs::path f = withUri("../outside.bin");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
              f.string() + ": /objects/0/gltf: " + model.string() +
                         ": /buffers/0/uri: '..' is not allowed in '../outside.bin'"));
  f = withUri("/etc/hostname");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
              f.string() + ": /objects/0/gltf: " + model.string() +
                         ": /buffers/0/uri: absolute path '/etc/hostname' is not allowed"));
  f = withUri("file:///etc/hostname");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /objects/0/gltf: " + model.string() +
                ": /buffers/0/uri: 'file:///etc/hostname': only relative paths and data: URIs are allowed");
  f = withUri("%2E%2E/outside.bin");  // percent-encoded ".."
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), ": /buffers/0/uri: '..' is not allowed"));
  // A raw '%' decoded with the two characters after it as hex: "100%.bin" searched "100" (a
  // new-user review); %00, a NUL, ends a path as early.
  write("models/100%.bin", std::string(12, '\0'));
  f = withUri("100%.bin");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /objects/0/gltf: " + model.string() +
                ": /buffers/0/uri: '100%.bin': a '%' not followed by two hex digits (a URI writes '%' as %25)");
  f = withUri("100%25.bin");
  EXPECT_NO_THROW(loadScene(f));
  f = withUri("a%00.bin");
  EXPECT_EQ(errorOf([&] { loadScene(f); }), f.string() + ": /objects/0/gltf: " + model.string() +
                                                ": /buffers/0/uri: 'a%00.bin': %00, a NUL character, in a path");
  f = withUri("missing.bin");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /objects/0/gltf: " + model.string() +
                ": /buffers/0/uri: file not found: " + (mDir / "models/missing.bin").string());
}

TEST_F(SceneFolder, GltfImagesMustStayInsideAndBePngOrJpeg) {
  write("../outside.png", "x");
  write("models/m.gltf", R"({"asset": {"version": "2.0"}, "images": [{"uri": "../../outside.png"}]})");
  fs::path f = scene(R"("a": {})", "", R"({"gltf": "models/m.gltf"})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "m.gltf: /images/0/uri: '..' is not allowed"));
  write("models/sky.exr", std::string("\x76\x2f\x31\x01", 4) + "OpenEXR");
  write("models/m.gltf", R"({"asset": {"version": "2.0"}, "images": [{"uri": "sky.exr"}]})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "m.gltf: /images/0: OpenEXR images are not supported (only PNG and JPEG)"));
}

TEST_F(SceneFolder, ABrokenTextureIsNamedOnce) {
  // A PNG signature and nothing after it: the PNG check names the file, the loader does not again.
  write("cut.png", std::string("\x89PNG\r\n\x1a\n", 8));
  fs::path f = sceneWithMaterial(R"({"base_colour_texture": "cut.png"})");
  const std::string error = errorOf([&] { loadScene(f); });
  const std::string png = (mDir / "cut.png").string();
  EXPECT_TRUE(contains(error, "/materials/m/base_colour_texture: " + png + ": ")) << error;
  EXPECT_EQ(error.find(png + ": " + png), std::string::npos) << error;
}

TEST_F(SceneFolder, GltfFactorsOutOfRangeNameThePlaceInTheGltf) {
  std::string text;
  {
    std::ifstream in(kFixtures / "quad.gltf");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  auto withMetallic = [&](const std::string& value) {
    std::string t = text;
    std::string key = "\"metallicFactor\": 0.25";
    t.replace(t.find(key), key.size(), "\"metallicFactor\": " + value);
    write("m.gltf", t);
    return scene(R"("a": {})", "", R"({"gltf": "m.gltf"})");
  };
  fs::path f = withMetallic("2");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /objects/0/gltf: " + (mDir / "m.gltf").string() +
                ": /materials/0/pbrMetallicRoughness/metallicFactor: expected a number in [0, 1], got 2.0");
  // JSON has no infinity; a number too large for a double is an error of the file itself.
  f = withMetallic("1e999");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
                         f.string() + ": /objects/0/gltf: " + (mDir / "m.gltf").string() + ":15:" ));
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), ": malformed JSON: number overflow parsing '1e999'"));
}

TEST_F(SceneFolder, GltfPrimitivesMustBeTriangles) {
  std::string text;
  {
    std::ifstream in(kFixtures / "quad.gltf");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string key = "\"indices\": 3, ";
  text.replace(text.find(key), key.size(), key + "\"mode\": 1, ");
  write("m.gltf", text);
  fs::path f = scene(R"("a": {})", "", R"({"gltf": "m.gltf"})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "m.gltf: /meshes/0/primitives/0/mode: only triangles (mode 4) are supported, got 1"));
}

TEST_F(SceneFolder, GltfVerticesMustLandWithinTheScenesRange) {
  copyFixture("quad.gltf");  // its vertices reach (1, 3, 4) through its nodes
  fs::path f = scene(R"("a": {})", "", R"({"gltf": "quad.gltf", "transform": {"scale": 2e11}})");
  EXPECT_NO_THROW(loadScene(f));  // 8e11 at most
  f = scene(R"("a": {})", "", R"({"gltf": "quad.gltf", "transform": {"scale": 1e12}})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "/objects/0/transform: a vertex lands at ("));
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "once placed: past ±1e12"));
}

TEST_F(SceneFolder, GltfMustBeVersionTwo) {
  std::string text;
  {
    std::ifstream in(kFixtures / "quad.gltf");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string key = "\"version\": \"2.0\"";
  ASSERT_NE(text.find(key), std::string::npos);
  write("m.gltf", std::string(text).replace(text.find(key), key.size(), "\"version\": \"1.0\""));
  fs::path f = scene(R"("a": {})", "", R"({"gltf": "m.gltf"})");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "m.gltf: /asset/version: glTF 1.0: Prism reads glTF 2.x"));
  write("m.gltf", "{}");
  EXPECT_TRUE(contains(errorOf([&] { loadScene(f); }), "m.gltf: /: missing required key 'asset'"));
}

TEST_F(SceneFolder, NonFiniteVertexDataIsAnErrorNotANaNPixel) {
  // glTF buffers are raw floats and may hold NaN: refused at load, naming the accessor element,
  // so that no NaN normal or position ever reaches the G-buffer.
  const float positions[9] = {0, 0, 0, 1, std::numeric_limits<float>::quiet_NaN(), 0, 0, 1, 0};
  {
    std::ofstream bin(mDir / "nan.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
  }
  write("nan.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "buffers": [{"uri": "nan.bin", "byteLength": 36}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}]})");
  fs::path f = scene(R"("a": {})", "", R"({"gltf": "nan.gltf"})");
  std::string error = errorOf([&] { loadScene(f); });
  EXPECT_TRUE(contains(error, "nan.gltf: ")) << error;
  EXPECT_TRUE(contains(error, "element 1 is not finite")) << error;
}

// The example scenes in scenes/ are what users start from: each must load.
TEST(SceneLoader, ExampleScenesLoad) {
  fs::path dir = PRISM_EXAMPLE_SCENE_DIR;
  if (!fs::exists(dir)) GTEST_SKIP() << dir << " does not exist";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    try {
      Scene s = loadScene(entry.path());
      EXPECT_FALSE(s.meshes.empty()) << entry.path();
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GT(count, 0);
}

// What a scene read, so that an output is never one of them: the glTF model, its buffer and its
// textures, each named; an output elsewhere passes.
TEST(SceneLoader, AnOutputIsNoneOfTheFilesTheSceneRead) {
  const fs::path dir = PRISM_EXAMPLE_SCENE_DIR;
  const Scene s = loadScene(dir / "textured_gltf.json");
  for (const char* file : {"tiles.gltf", "tiles.bin", "tiles_base_colour.png", "tiles_normal.png"}) {
    EXPECT_TRUE(std::ranges::any_of(s.files, [&](const fs::path& f) { return f.filename() == file; })) << file;
    try {
      requireNotSceneInput(dir / "models" / file, s);
      ADD_FAILURE() << file << ": no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("is also a file the scene reads"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(requireNotSceneInput(dir / "textured_gltf.json", s), Error);
  EXPECT_NO_THROW(requireNotSceneInput(fs::path(::testing::TempDir()) / "textured_gltf.png", s));
  EXPECT_NO_THROW(requireNotSceneInput(dir / "models" / "reef_sand.png", s));  // beside them, not read
  EXPECT_NO_THROW(requireNotSceneInput(dir / "textured_gltf.png", s));
}

}  // namespace
}  // namespace prism


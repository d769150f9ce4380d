// The scene loader and the techniques' sections (water, the atmosphere, PRT): each section read
// into the scene, its lights added, its values checked with the file and the place named.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/error_test_support.h"
#include "scene/scene_folder_test_support.h"
#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/prt/prt_section.h"
#include "techniques/underwater/jerlov_water.h"
#include "techniques/underwater/water_section.h"

namespace prism {
namespace {

using namespace testing_support;

TEST_F(SceneFolder, WaterIsAJerlovTypeAtADepthWithItsMultipliers) {
  fs::path f = write("water.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]}, "objects": [],
    "water": {"type": "3C", "depth": 12, "scattering_scale": 2, "absorption_scale": 0.5, "kd_scale": 1.5}})");
  Scene s = loadScene(f);
  const auto* w = s.techniques.find<underwater::WaterSection>();
  ASSERT_TRUE(w);
  EXPECT_EQ(w->type, "3C");
  EXPECT_FLOAT_EQ(w->depthM, 12.0f);
  EXPECT_FLOAT_EQ(w->surfaceY(s.camera.position.y), 13.0f);
  underwater::WaterProperties water = underwater::jerlovWater("3C");
  EXPECT_NEAR(w->sigmaS.at(500.0), 2.0 * water.sigmaS.at(500.0), 1e-12);
  EXPECT_NEAR(w->sigmaA.at(500.0), 0.5 * water.sigmaA.at(500.0), 1e-12);
  EXPECT_NEAR(w->kd.at(500.0), 1.5 * water.kd.at(500.0), 1e-12);
  EXPECT_TRUE(w->lampScattering);
  // The command line changes it like any other value.
  EXPECT_EQ(errorOf([&] { loadScene(f, {"water.type=9C", "water.dataset=williamson2022"}); }),
            f.string() + ": /water/type (set on the command line): unknown water type \"9C\" in the williamson2022 data (known: IB, II, "
                         "III, 1C, 3C, 5C)");
  Scene t = loadScene(f, {"water.type=5C", "water.depth=20", "water.dataset=williamson2022"});
  EXPECT_FLOAT_EQ(t.techniques.find<underwater::WaterSection>()->depthM, 20.0f);
  EXPECT_FALSE(loadScene(f, {"water.lamp_scattering=false"}).techniques.find<underwater::WaterSection>()->lampScattering);
  EXPECT_EQ(errorOf([&] { loadScene(f, {"water.lamp_scattering=1"}); }),
            f.string() + ": /water/lamp_scattering (set on the command line): expected true or false, got 1");
  // The bench times the lamps' in-scattering only where there are lamps and it is on.
  auto timesUnscattered = [](const TechniqueBench& b) {
    return std::ranges::any_of(b.configs, [](const TechniqueBenchConfig& c) { return c.label == "16 wet, lamps unscattered"; });
  };
  EXPECT_TRUE(timesUnscattered(w->bench(1)));
  EXPECT_FALSE(timesUnscattered(w->bench(0)));
  EXPECT_FALSE(timesUnscattered(
      loadScene(f, {"water.lamp_scattering=false"}).techniques.find<underwater::WaterSection>()->bench(1)));
  EXPECT_EQ(errorOf([&] { loadScene(f, {"water.type=IV"}); }),
            f.string() + ": /water/type (set on the command line): unknown water type \"IV\" in the jerlov data (known: I, IA, IB, II, III, "
                         "1C, 3C, 5C, 7C, 9C)");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"water.depth=-1"}); }),
            f.string() + ": /water/depth (set on the command line): expected a number in [0, 1e+12], got -1");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"water.salinity=35"}); }),
                         f.string() + ": /water/salinity (set on the command line): unknown key (allowed: "));
}

TEST_F(SceneFolder, AtmosphereAddsTheSunAsALightAndChecksItsParameters) {
  fs::path f = write("sky.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]}, "objects": [],
    "atmosphere": {"sun": {"elevation": 30, "azimuth": 90}, "turbidity": 0.02, "ozone": 350, "ground_altitude": 500}})");
  Scene s = loadScene(f);
  auto* sky = s.techniques.find<atmosphere::AtmosphereSection>();
  ASSERT_TRUE(sky);
  EXPECT_DOUBLE_EQ(sky->parameters.mieAngstromBeta, 0.02);
  EXPECT_DOUBLE_EQ(sky->parameters.ozoneColumnDu, 350.0);
  EXPECT_FLOAT_EQ(sky->groundAltitudeM, 500.0f);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& sun = s.lights[0];
  EXPECT_EQ(sun.technique, "atmosphere");
  // Towards +x (azimuth 90°), 30° up; the light travels the other way.
  EXPECT_NEAR(sun.direction.x, -std::cos(glm::radians(30.0f)), 1e-6);
  EXPECT_NEAR(sun.direction.y, -0.5f, 1e-6);
  EXPECT_NEAR(sun.direction.z, 0.0f, 1e-6);
  // The solar constant's visible part: ASTM G-173's extraterrestrial spectrum gives about 133 klux.
  EXPECT_NEAR(sun.intensity, 1.33e5f, 0.03e5f);
  EXPECT_NEAR(luminousIntegral(sun.spd), 1.0, 1e-9);
  // applyTechniqueLights follows edits of the angles, and a copy of the scene has its own section.
  Scene copy = s;
  sky->sunElevationDeg = 90.0f;
  applyTechniqueLights(s);
  applyTechniqueLights(copy);
  EXPECT_NEAR(copy.lights[0].direction.y, -0.5f, 1e-6);
  EXPECT_NEAR(s.lights[0].direction.y, -1.0f, 1e-6);

  EXPECT_EQ(errorOf([&] { loadScene(f, {"atmosphere.sun.elevation=95"}); }),
            f.string() + ": /atmosphere/sun/elevation (set on the command line): expected a number in [-90, 90], got 95");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"atmosphere.mie_g=1"}); }),
            f.string() + ": /atmosphere/mie_g (set on the command line): expected a number in (-1, 1), got 1");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"atmosphere.atmosphere_height=40", "atmosphere.ground_altitude=45000"}); }),
            f.string() + ": /atmosphere/ground_altitude (set on the command line): 45000 m must be below the top of the atmosphere (40 km)");
  // The height must hold the ozone layer and the scale heights, said at the key (it named the
  // ozone layer's parameters, which a scene cannot set, at /atmosphere).
  EXPECT_EQ(errorOf([&] { loadScene(f, {"atmosphere.atmosphere_height=20"}); }),
            f.string() + ": /atmosphere/atmosphere_height (set on the command line): 20 km is below the ozone layer (peak at 25 km, half-width 15 km): at least 25");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"atmosphere.rayleigh_scale_height=80"}); }),
            f.string() + ": /atmosphere/rayleigh_scale_height (set on the command line): 80 km is above the atmosphere's height (60 km)");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"atmosphere.humidity=3"}); }),
                         f.string() + ": /atmosphere/humidity (set on the command line): unknown key (allowed: "));
  // A radius alone keeps the height of the defaults `a` holds, whatever radius they had (it was
  // their top less Earth's 6360 km: a Mars-sized default would have lost its atmosphere).
  atmosphere::AtmosphereSky mars;
  mars.parameters.bottomRadiusKm = 3390.0;
  mars.parameters.topRadiusKm = 3490.0;
  const nlohmann::json radius = {{"planet_radius", 3000}};
  const schema::Document document{"mars", {}};
  atmosphere::readAtmosphereKeys(schema::Node(radius, "", document), mars);
  EXPECT_DOUBLE_EQ(mars.parameters.topRadiusKm, 3100.0);
  fs::path both = write("both.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]}, "objects": [],
    "water": {"type": "I"}, "atmosphere": {}})");
  EXPECT_EQ(errorOf([&] { loadScene(both); }), both.string() + ": /atmosphere: a scene has water or an atmosphere, not both");
}

TEST_F(SceneFolder, PrtObjectsNameTheTechniqueAndItsSectionIsChecked) {
  fs::path f = write("prt.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
    "materials": {"m": {}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "m", "technique": "prt"},
                {"box": {"centre": [2, 0, 0], "size": [1, 1, 1]}, "material": "m"}],
    "prt": {"environment": {"illuminant": "F4", "shape": "uniform", "luminance": 500, "rotation_deg": 30},
            "basis": 6, "mode": "rgb-prt", "samples": 64, "shadows": false}})");
  Scene s = loadScene(f);
  EXPECT_EQ(s.meshes[0].technique, "prt");
  EXPECT_EQ(s.meshes[1].technique, "");
  const auto* prt = s.techniques.find<prt::PrtSection>();
  ASSERT_TRUE(prt);
  EXPECT_TRUE(prt->shadesObjects());
  EXPECT_EQ(prt->illuminant, "F4");
  EXPECT_EQ(prt->shape, "uniform");
  EXPECT_FLOAT_EQ(prt->luminanceCdM2, 500.0f);
  EXPECT_FLOAT_EQ(prt->rotationDeg, 30.0f);
  EXPECT_EQ(prt->basis, 6);
  EXPECT_EQ(prt->mode, prt::PrtMode::RgbPrt);
  EXPECT_EQ(prt->samples, 64);
  EXPECT_FALSE(prt->shadows);
  // Defaults: a D65 sky of 1000 cd/m², m = 8, spectral.
  Scene d = loadScene(f, {"prt={}"});
  const auto* defaults = d.techniques.find<prt::PrtSection>();
  EXPECT_EQ(defaults->illuminant, "D65");
  EXPECT_EQ(defaults->shape, "sky");
  EXPECT_EQ(defaults->basis, 8);
  EXPECT_EQ(defaults->mode, prt::PrtMode::Spectral);

  EXPECT_EQ(errorOf([&] { loadScene(f, {"prt.basis=17"}); }),
            f.string() + ": /prt/basis (set on the command line): expected an integer in [1, 16], got 17");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"prt.mode=rgb"}); }),
            f.string() + ": /prt/mode (set on the command line): expected \"spectral\", \"rgb-prt\" or \"reference-5nm\", got \"rgb\"");
  EXPECT_EQ(errorOf([&] { loadScene(f, {"prt.environment.shape=dome"}); }),
            f.string() + ": /prt/environment/shape (set on the command line): expected \"sky\" or \"uniform\", got \"dome\"");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"prt.environment.illuminant=F99"}); }),
                         f.string() + ": /prt/environment/illuminant (set on the command line): "));
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"prt.environment.map=sky.exr"}); }),
                         f.string() + ": /prt/environment/illuminant: give one of a map, an atmosphere, or an illuminant and shape"));
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"prt.environment={\"map\": \"missing.exr\"}"}); }),
                         f.string() + ": /prt/environment/map (set on the command line): "));
  write("bad.exr", "not an exr");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f, {"prt.environment={\"map\": \"bad.exr\"}"}); }),
                         f.string() + ": /prt/environment/map (set on the command line): "));
  // An object naming a technique the scene lacks, or one that does not shade objects.
  fs::path orphan = write("orphan.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
    "materials": {"m": {}}, "water": {},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "m", "technique": "prt"}]})");
  EXPECT_EQ(errorOf([&] { loadScene(orphan); }),
            orphan.string() + ": /objects/0/technique: the scene has no 'prt' section to shade this object");
  EXPECT_EQ(errorOf([&] { loadScene(orphan, {"objects.0.technique=water"}); }),
            orphan.string() + ": /objects/0/technique (set on the command line): 'water' does not shade objects");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(orphan, {"objects.0.technique=PRT"}); }),
                         orphan.string() + ": /objects/0/technique (set on the command line): 'PRT' is no technique (known: "));
}

// The viewer's PRT panel switches the spectral sky's sun disc: the sun is the scene's light, so
// switching it on must add that light and switching it off take it away. Loaded without it, the
// switch added no light (applyTechniqueLights only pointed lights already there), and a sun
// switched off kept shining on every surface.
TEST_F(SceneFolder, PrtSunDiscSwitchedAddsOrTakesAwayItsLight) {
  fs::path f = write("prt_sky.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
    "materials": {"m": {}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "m", "technique": "prt"}],
    "lights": [{"type": "point", "position": [0, 3, 0], "spd": "A", "intensity": 100}],
    "prt": {"environment": {"atmosphere": {"sun": {"elevation": 20}, "sun_disc": false}}}})");
  Scene s = loadScene(f);
  ASSERT_EQ(s.lights.size(), 1u);
  prt::PrtSection& section = *s.techniques.find<prt::PrtSection>();
  section.sky->sunDisc = true;
  applyTechniqueLights(s);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].technique, "");
  const Light& sun = s.lights[1];
  EXPECT_EQ(sun.technique, "prt");
  EXPECT_EQ(sun.type, LightType::Directional);
  // As loaded with the disc on: the same light, direction, spectrum and illuminance.
  const Scene loadedOn = loadScene(f, {"prt.environment.atmosphere.sun_disc=true"});
  ASSERT_EQ(loadedOn.lights.size(), 2u);
  EXPECT_GT(sun.intensity, 1e4f);
  EXPECT_EQ(sun.intensity, loadedOn.lights[1].intensity);
  EXPECT_EQ(sun.direction, loadedOn.lights[1].direction);
  EXPECT_EQ(sun.spd.at(550.0), loadedOn.lights[1].spd.at(550.0));
  EXPECT_EQ(sun.spdLabel, loadedOn.lights[1].spdLabel);
  // Off again: the scene's own light stays, the sun goes; applied twice, nothing more changes.
  section.sky->sunDisc = false;
  applyTechniqueLights(s);
  applyTechniqueLights(s);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].technique, "");
  EXPECT_EQ(s.lights[0].intensity, 100.0f);
}

}  // namespace
}  // namespace prism

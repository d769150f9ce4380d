// The environment the reference traces PRT scenes under is the one PRT projects: its radiance per
// direction, projected on SH-5 here by quadrature, gives the section's projected environment —
// for the sky gradient, a uniform illuminant and a turned map (which pins the y-up to z-up turn,
// the rotation's sense and the map's texel layout).
#include "techniques/prt/prt_environment_radiance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "core/worst_of.h"
#include "shared_cpp.h"
#include "spectral/illuminant.h"
#include "spectral/table_test_support.h"
#include "spectral/observer.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/prt_sky.h"
#include "techniques/prt/sh_tools.h"

namespace prism::prt {
namespace {

// The section's SH-5 environment at `lambdaNm` (a 5 nm grid wavelength) against the projection
// of `traced`'s radiance (the same section, unless a test shows it can tell them apart): the
// largest coefficient difference relative to the constant term.
double projectionDifference(const PrtSection& section, double lambdaNm, const PrtSection* traced = nullptr) {
  const RgbToSpectrumTable& table = smallSrgbTable();
  const Eigen::MatrixXd grid = environmentOnGrid(sectionEnvironment(section, table));
  const Eigen::RowVectorXd expected = grid.row(static_cast<Eigen::Index>(std::lround((lambdaNm - kGridMinNm) / kGridStepNm)));
  const std::shared_ptr<const TechniqueEnvironment> environment = environmentRadiance(traced ? *traced : section, table);
  // PRT's directions are z-up; the environment takes the world's (y-up): (x, y, z)_PRT = (x, −z, y)_world.
  const ShVector projected = projectOnSh(
      [&](const glm::dvec3& d) { return environment->radiance(glm::vec3(d.x, d.z, -d.y), lambdaNm); }, 512, 1024) *
      double(shared::kLumensPerWatt);  // the path tracer's radiance carries 683 lm/W in its luminance; PRT's does not
  double worst = 0.0;
  for (int k = 0; k < 25; ++k) worst = worstOf(worst, std::abs(projected[k] - expected[k]) / std::abs(expected[0]));
  return worst;
}

// A width × height map, no two texels alike.
std::shared_ptr<const PrtMap> testMap(int width, int height) {
  auto map = std::make_shared<PrtMap>();
  map->file = "test map";
  map->width = width;
  map->height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      map->linearRgb.insert(map->linearRgb.end(), {0.1f + 0.01f * static_cast<float>(x), 0.2f + 0.02f * static_cast<float>(y),
                                                   0.3f + 0.001f * static_cast<float>(x * y)});
  return map;
}

TEST(EnvironmentRadiance, ProjectsToTheSectionsEnvironment) {
  PrtSection sky;
  sky.illuminant = "F4";
  sky.luminanceCdM2 = 800.0f;
  sky.rotationDeg = 40.0f;  // a zonal environment: unchanged
  EXPECT_LT(projectionDifference(sky, 550.0), 2e-3);

  PrtSection uniform;
  uniform.illuminant = "A";
  uniform.shape = "uniform";
  EXPECT_LT(projectionDifference(uniform, 600.0), 1e-6);

  // A 128 × 64 map turned 30° about the zenith (the section integrates each texel's SH functions,
  // equirectangularTexelSh; by its centre alone it was 3.1e-4 here, and 2 % off on 16 × 8 texels).
  PrtSection mapped;
  mapped.map = testMap(128, 64);
  mapped.rotationDeg = 30.0f;
  const double turned = projectionDifference(mapped, 500.0);
  EXPECT_LT(turned, 1e-3);
  PrtSection otherWay = mapped;  // turned the other way: another environment, which the test tells apart
  otherWay.rotationDeg = -30.0f;
  EXPECT_GT(projectionDifference(mapped, 500.0, &otherWay), 20.0 * turned);
  std::printf("SH-5 coefficients of the projected radiance against the section's, worst relative to the constant "
              "term: sky %.2g, map turned 30° %.2g\n",
              projectionDifference(sky, 550.0), turned);
}

// A map's texels are light, as a background's colour is: (1, 1, 1) is the colour space's white,
// D65, in the environment PRT projects and in the one the path tracer traces. Upsampled as
// unbounded colours they were equal-energy white (x, y = ⅓), pink on screen (prt_rock's sky).
TEST(EnvironmentRadiance, AWhiteMapIsTheColourSpacesWhite) {
  const RgbToSpectrumTable& table = smallSrgbTable();
  auto white = std::make_shared<PrtMap>();
  white->file = "white map";
  white->width = 16;
  white->height = 8;
  white->linearRgb.assign(3 * 16 * 8, 1.0f);
  PrtSection section;
  section.map = white;
  const Eigen::Vector3d d65 = luminousTristimulus(illuminant("D65"));
  auto chromaticity = [](const Eigen::Vector3d& xyz) { return glm::dvec2(xyz[0], xyz[1]) / xyz.sum(); };
  const Eigen::MatrixXd grid = environmentOnGrid(sectionEnvironment(section, table));
  const Spectrum projected = Spectrum::fromFunction([&](double lambdaNm) {
    const double t = std::clamp((lambdaNm - kGridMinNm) / kGridStepNm, 0.0, kGridWavelengths - 1.0);
    const int i = std::min(static_cast<int>(t), kGridWavelengths - 2);
    return (1.0 - (t - i)) * grid(i, 0) + (t - i) * grid(i + 1, 0);  // the constant SH term
  });
  const auto traced = environmentRadiance(section, table);
  const Spectrum radiance =
      Spectrum::fromFunction([&](double lambdaNm) { return traced->radiance(glm::vec3(0.3f, 0.8f, 0.5f), lambdaNm); });
  // The 5 nm grid and the small table's white leave about 1e-3 in x and y.
  EXPECT_LT(glm::distance(chromaticity(luminousTristimulus(projected)), chromaticity(d65)), 2e-3);
  EXPECT_LT(glm::distance(chromaticity(luminousTristimulus(radiance)), chromaticity(d65)), 2e-3);
}

// What the water in-scatters of an environment (scalarIrradianceFromAbove, ∫ L dω over the sky):
// 2π·L for a uniform one; for the overcast gradient, linear in cos θ above the horizon,
// 2π·L_z·(1 + 2·½)/3 whatever the rotation, its ground below left out; for a map with a sun (one
// texel a thousand times the others), the sky's texels weighted by their solid angles — where the
// default quadrature, whose cells are 50 times a texel of a 0.5° sun, is off.
TEST(EnvironmentRadiance, ItsScalarIrradianceFromAboveIsTheSkysIntegral) {
  const RgbToSpectrumTable& table = smallSrgbTable();
  PrtSection uniform;
  uniform.illuminant = "A";
  uniform.shape = "uniform";
  const auto flat = environmentRadiance(uniform, table);
  const Spectrum e = flat->scalarIrradianceFromAbove();
  for (double lambdaNm : {400.0, 555.0, 700.0}) {
    const double l = flat->radiance(glm::vec3(0.0f, 1.0f, 0.0f), lambdaNm);
    EXPECT_NEAR(e.at(lambdaNm), 2.0 * std::numbers::pi * l, 1e-12 * l) << lambdaNm;
  }

  PrtSection sky;
  sky.illuminant = "F4";
  sky.rotationDeg = 70.0f;
  const auto overcast = environmentRadiance(sky, table);
  const double zenith = overcast->radiance(glm::vec3(0.0f, 1.0f, 0.0f), 545.0);
  EXPECT_NEAR(overcast->scalarIrradianceFromAbove().at(545.0), 2.0 * std::numbers::pi * zenith * 2.0 / 3.0, 1e-9 * zenith);

  auto sunny = std::make_shared<PrtMap>(*testMap(61, 30));
  for (int c = 0; c < 3; ++c) sunny->linearRgb[3 * (5 * 61 + 17) + static_cast<std::size_t>(c)] *= 1000.0f;
  PrtSection mapped;
  mapped.map = sunny;
  const PrtMap& map = *mapped.map;
  const auto texels = environmentRadiance(mapped, table);
  // The map's upper half summed texel by texel (its rows 0–14 lie above the horizon).
  double expected = 0.0;
  for (int y = 0; y < map.height / 2; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const EquirectangularTexel t = equirectangularTexel(x, y, map.width, map.height);
      expected += t.solidAngle * texels->radiance(glm::vec3(t.direction.x, t.direction.z, -t.direction.y), 610.0);
    }
  }
  const double got = texels->scalarIrradianceFromAbove().at(610.0);
  const double quadrature = texels->TechniqueEnvironment::scalarIrradianceFromAbove().at(610.0);
  std::printf("scalar irradiance from above of a 61 × 30 map with a sun at 610 nm: %.6g, its texels' sum %.6g, "
              "the default quadrature %.6g\n", got, expected, quadrature);
  EXPECT_NEAR(got, expected, 1e-9 * expected);
  EXPECT_GT(std::abs(quadrature - expected), 0.01 * expected);
}

// A map's sum is made once per map and kept (under water the scene asks for it on every change):
// turning the environment about the zenith keeps it, its luminance scales it, and a new map — an
// edit makes one; copies of the scene share the old — gets its own.
TEST(EnvironmentRadiance, AMapsSumIsKeptPerMapAndFollowsItsEdits) {
  const RgbToSpectrumTable& table = smallSrgbTable();
  PrtSection section;
  section.map = testMap(40, 20);
  const double first = environmentRadiance(section, table)->scalarIrradianceFromAbove().at(550.0);
  section.rotationDeg = 120.0f;
  EXPECT_EQ(environmentRadiance(section, table)->scalarIrradianceFromAbove().at(550.0), first);
  section.luminanceCdM2 *= 3.0f;
  EXPECT_NEAR(environmentRadiance(section, table)->scalarIrradianceFromAbove().at(550.0), 3.0 * first, 1e-12 * first);
  auto edited = std::make_shared<PrtMap>(*section.map);
  for (float& v : edited->linearRgb) v *= 2.0f;
  section.map = edited;
  EXPECT_NEAR(environmentRadiance(section, table)->scalarIrradianceFromAbove().at(550.0), 6.0 * first, 1e-6 * first);
}

// The default quadrature, on a smooth environment: L = L_z·max(0, cos θ) gives π·L_z, exactly at
// its 5 nm nodes (the rule is exact for radiance linear in cos θ).
TEST(EnvironmentRadiance, TheDefaultScalarIrradianceIsExactForACosineSky) {
  struct CosineSky final : TechniqueEnvironment {
    double radiance(const glm::vec3& d, double lambdaNm) const override { return std::max(0.0f, d.y) * (1.0 + lambdaNm / 1000.0); }
  };
  const Spectrum e = CosineSky().scalarIrradianceFromAbove();
  for (double lambdaNm : {360.0, 545.0, 830.0}) {
    EXPECT_NEAR(e.at(lambdaNm), std::numbers::pi * (1.0 + lambdaNm / 1000.0), 1e-9) << lambdaNm;
  }
}

// Prism's spectral sky, the sun 25° high at azimuth 130°, turned 40° about the zenith.
PrtSection turnedSpectralSky() {
  PrtSection section;
  PrtSky sky;
  sky.atmosphere.sunElevationDeg = 25.0f;
  sky.atmosphere.sunAzimuthDeg = 130.0f;
  section.sky = sky;
  section.rotationDeg = 40.0f;
  return section;
}

TEST(EnvironmentRadiance, ProjectsToTheSectionsEnvironmentUnderTheSpectralSky) {
  // Its sun is the scene's light, not part of it: the traced radiance (the grid's nearest texel)
  // is what PRT projects.
  PrtSection section = turnedSpectralSky();
  const double turned = projectionDifference(section, 550.0);
  EXPECT_LT(turned, 1e-3);
  PrtSection otherWay = section;
  otherWay.rotationDeg = -40.0f;
  EXPECT_GT(projectionDifference(section, 550.0, &otherWay), 20.0 * turned);
  std::printf("the spectral sky turned 40°: worst %.2g\n", turned);
}

TEST(EnvironmentRadiance, TheSpectralSkysSunIsALightTurnedWithIt) {
  // Azimuth 0: towards −z, 90: +x; turned 40° counter-clockwise seen from above, the sun's 130°
  // becomes 90°, towards +x.
  PrtSection section = turnedSpectralSky();
  std::optional<TechniqueLight> sun = section.light();
  ASSERT_TRUE(sun);
  const double e = glm::radians(25.0);
  const glm::vec3 towardsSun = -sun->direction;
  EXPECT_NEAR(towardsSun.y, std::sin(e), 1e-5);
  EXPECT_NEAR(towardsSun.x, std::cos(e), 1e-5);
  EXPECT_NEAR(towardsSun.z, 0.0, 1e-5);
  EXPECT_TRUE(sun->followsSection);
  // Its spectrum is the disc's irradiance on the ground, the grid's.
  EXPECT_DOUBLE_EQ(sun->spd.at(550.0), sectionSky(*section.sky)->sunIrradianceAt(550.0));
  section.sky->sunDisc = false;
  EXPECT_FALSE(section.light());
  section.sky->sunDisc = true;
  section.sky->atmosphere.sunElevationDeg = -4.0f;  // below the horizon: a light that is out
  sun = section.light();
  ASSERT_TRUE(sun);
  EXPECT_EQ(sun->illuminanceLux, 0.0);
}

// What has no lights (`prt report`) takes the spectral sky's sun into the environment, on SH-5, as
// `prt report --environment atmosphere` does; the renderer's environment leaves it to the light.
// The report on a scene's sky left the sun out (prt_sky.json: 0.276 max ΔE94 at m = 8 against
// 0.938 for the same sky by --environment atmosphere) while its header named the sun.
TEST(EnvironmentRadiance, WithoutLightsTheSpectralSkysSunIsInTheEnvironment) {
  const RgbToSpectrumTable& table = smallSrgbTable();
  PrtSection section = turnedSpectralSky();
  section.rotationDeg = 0.0f;
  const Eigen::MatrixXd withSun = environmentOnGrid(sectionEnvironment(section, table, true));
  const Eigen::MatrixXd skyAlone = environmentOnGrid(sectionEnvironment(section, table));
  const Eigen::MatrixXd atmosphere =
      environmentOnGrid(skyEnvironment("", *sectionSky(*section.sky), true, double(shared::kLumensPerWatt)));
  EXPECT_LE((withSun - atmosphere).cwiseAbs().maxCoeff(), 1e-12 * atmosphere.cwiseAbs().maxCoeff());
  const double litY = sceneWhite(withSun, cie1931Observer()).y(), skyY = sceneWhite(skyAlone, cie1931Observer()).y();
  std::printf("the spectral sky, sun 25° high: white Y %.4g with its sun, %.4g without\n", litY, skyY);
  EXPECT_GT(litY, 2.0 * skyY);
  section.sky->sunDisc = false;  // no sun to take in
  EXPECT_EQ(environmentOnGrid(sectionEnvironment(section, table, true)), skyAlone);
}

}  // namespace
}  // namespace prism::prt

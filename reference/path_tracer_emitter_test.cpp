// Global transport aims at emitting surfaces (emitter_sampler.h) and weighs that against the
// BRDF's own samples: held to a closed form, to the noise a BRDF sample alone would leave, and to
// a sky of the same luminance on glossy floors (the weights).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "reference/path_tracer.h"
#include "reference/path_tracer_test_support.h"
#include "scene/procedural_mesh.h"
#include "scene/scene_loader.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::reference {
namespace {

// A floor of albedo ρ under a square lamp of side 2a, L cd/m², at height h, facing it, in the
// dark: the floor point below the lamp's centre has irradiance 4L·A/√(1+A²)·atan(A/√(1+A²)),
// A = a/h (four corners of the parallel rectangle's form factor), so radiance ρ·E/π. A BRDF sample
// meets the lamp with a chance of E/(πL) (7 % here); aimed at, nearly every path brings its light.
TEST(PathTracerEmitters, ASmallLampLightsTheFloorAsItsFormFactorSays) {
  const double rho = 0.5, luminance = 1000.0, a = 0.25, h = 1.0;
  Scene scene;
  scene.camera.position = {0.0f, 0.5f, 3.0f};  // below the lamp, looking at the floor under it
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  Material floor;
  floor.lambertian = true;
  floor.reflectance = Spectrum::constant(rho);
  scene.materials = {floor, test::d65Emitter(static_cast<float>(luminance))};
  scene.meshes.push_back(makePlane({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {20.0f, 20.0f}));
  scene.meshes.push_back(makePlane({0.0f, static_cast<float>(h), 0.0f}, {0.0f, -1.0f, 0.0f},
                                   {static_cast<float>(2 * a), static_cast<float>(2 * a)}));
  scene.meshes.back().material = 1;

  ReferenceSettings settings;
  settings.width = settings.height = 1;  // the one pixel's centre is the camera's target
  settings.samplesPerPixel = 4096;
  settings.filter = PixelFilter::Centre;
  settings.transport = LightTransport::Global;
  const ReferenceImage image = renderReference(scene, rendererRgbToSpectrumTable("srgb"), settings);

  const double q = (a / h) / std::sqrt(1.0 + (a / h) * (a / h));
  const double expected = rho * 4.0 * luminance * q * std::atan(q) / std::numbers::pi;  // Y, cd/m²
  const double y = image.tristimulus.pixels[1];
  const double sigma = std::sqrt(static_cast<double>(image.variance.pixels[1]));
  // One path's standard deviation over the mean: BRDF samples alone give ≈ √((1 − p)/p) ≈ 3.6
  // at p = 7 % (plus the wavelengths' share).
  const double pathSpread = sigma * std::sqrt(static_cast<double>(settings.samplesPerPixel)) / y;
  std::printf("floor under the lamp: Y %.4f (closed form %.4f), z %.2f, one path's spread %.3f of the mean\n", y,
              expected, (y - expected) / sigma, pathSpread);
  EXPECT_LT(std::abs(y - expected), 5.0 * sigma);
  EXPECT_NEAR(y / expected, 1.0, 0.01);
  EXPECT_LT(pathSpread, 1.0);
  // Its chromaticity is the lamp's (a grey floor).
  const Eigen::Vector3d xyz = observer("cie1931").integrate(illuminant("D65"));
  EXPECT_NEAR(image.tristimulus.pixels[0] / y, xyz.x() / xyz.y(), 0.01);
  EXPECT_NEAR(image.tristimulus.pixels[2] / y, xyz.z() / xyz.y(), 0.01);
}

// `scene` (its first mesh a floor seen from above, background white) under global transport twice:
// under a background of `luminance` cd/m², and inside an emitting sphere of that luminance, 100 m
// round it, instead. Each channel's mean over pixels is compared, in units of their standard error
// (the variance images) and relatively; `what` names the case.
void expectTheSphereIsTheSky(const Scene& scene, float luminance, int samplesPerPixel, const std::string& what) {
  ReferenceSettings settings;
  settings.width = 24;
  settings.height = 16;
  settings.samplesPerPixel = samplesPerPixel;
  settings.filter = PixelFilter::Centre;
  settings.transport = LightTransport::Global;
  Scene sky = scene;
  sky.backgroundLuminance = luminance;
  Scene inside = scene;
  inside.materials.push_back(test::d65Emitter(luminance));
  inside.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 100.0f, 64));
  inside.meshes.back().material = static_cast<int>(inside.materials.size()) - 1;
  const RgbToSpectrumTable& table = rendererRgbToSpectrumTable("srgb");
  const ReferenceImage images[2] = {renderReference(sky, table, settings), renderReference(inside, table, settings)};
  const std::size_t n = images[0].tristimulus.pixelCount();
  const double nd = static_cast<double>(n);
  for (std::size_t channel = 0; channel < 3; ++channel) {
    double mean[2] = {0.0, 0.0}, variance[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
      for (std::size_t p = 0; p < n; ++p) {
        mean[i] += images[i].tristimulus.pixels[3 * p + channel] / nd;
        variance[i] += images[i].variance.pixels[3 * p + channel] / (nd * nd);
      }
    }
    const double sigma = std::sqrt(variance[0] + variance[1]);
    std::printf("%s, channel %zu: under the sky %.4f, inside the sphere %.4f, z %.2f\n", what.c_str(), channel, mean[0],
                mean[1], (mean[1] - mean[0]) / sigma);
    EXPECT_LT(std::abs(mean[1] - mean[0]), 5.0 * sigma) << what << ", channel " << channel;
    EXPECT_NEAR(mean[1] / mean[0], 1.0, 0.01) << what << ", channel " << channel;
  }
}

// A glossy floor inside an emitting sphere of luminance L sees L over its whole sky, as under a
// background of L: the two images are the same up to their noise. Under the sphere, light comes
// from both the emitters aimed at and BRDF samples, weighed by the power heuristic; under the
// background, from BRDF samples alone. A weight or a BRDF density (brdfPdf) that did not match
// what sampleBrdf draws would part them, most on the sharp lobes.
TEST(PathTracerEmitters, AGlossyFloorInsideAnEmittingSphereIsTheFloorUnderASkyOfItsLuminance) {
  struct Case {
    float metallic, roughness;
  };
  for (const Case c : {Case{0.0f, 0.5f}, Case{0.0f, 0.1f}, Case{1.0f, 0.25f}, Case{1.0f, 0.05f}}) {
    Material floor;
    floor.baseColour = glm::vec3(0.7f, 0.5f, 0.3f);
    floor.metallic = c.metallic;
    floor.roughness = c.roughness;
    Scene scene = test::floorSeenFromAbove(floor);
    scene.background = glm::vec3(1.0f);  // D65 in sRGB, the sphere's spectrum
    expectTheSphereIsTheSky(scene, 40.0f, 256,
                            fmt::format("metallic {:.0f}, roughness {:.2f}", c.metallic, c.roughness));
  }
}

// The same in a body of fog over the floor (its region a box the camera looks into from above),
// under global transport: emitters are aimed at from the medium's scattering points too, weighed
// against the phase function's own direction.
TEST(PathTracerEmitters, AFloorUnderFogInsideAnEmittingSphereIsTheFloorUnderASkyOfItsLuminance) {
  Material floor;
  floor.lambertian = true;
  floor.reflectance = Spectrum::constant(0.6);
  Scene scene = test::floorSeenFromAbove(floor);
  scene.background = glm::vec3(1.0f);
  HomogeneousMedium fog;
  fog.sigmaA = Spectrum::constant(0.1);
  fog.sigmaS = Spectrum::constant(0.4);
  fog.g = 0.6f;
  fog.region = Bounds{{-10.0f, -1.0f, -10.0f}, {10.0f, 2.0f, 10.0f}};
  scene.medium = fog;
  expectTheSphereIsTheSky(scene, 40.0f, 1024, "fog");  // 1 024 paths: the image's mean to 0.2 %
}

// The example room the README measures this with (scenes/reference/lamp_room.json) loads, and its
// lamp alone lights it: under direct transport, which aims at the lights (none), every pixel but
// the lamp's own is black; under global transport those pixels are lit.
TEST(PathTracerEmitters, TheExampleRoomIsLitByItsLampUnderGlobalTransport) {
  const Scene scene = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "reference" / "lamp_room.json");
  ASSERT_TRUE(scene.lights.empty());
  ReferenceSettings settings;
  settings.width = 16;
  settings.height = 12;
  settings.samplesPerPixel = 16;
  const RgbToSpectrumTable& table = rendererRgbToSpectrumTable("srgb");
  settings.transport = LightTransport::Direct;
  const ReferenceImage direct = renderReference(scene, table, settings);
  settings.transport = LightTransport::Global;
  const ReferenceImage global = renderReference(scene, table, settings);
  int dark = 0;
  double litY = 0.0;
  for (std::size_t i = 0; i < direct.tristimulus.pixelCount(); ++i) {
    if (direct.tristimulus.pixels[3 * i + 1] != 0.0f) continue;  // the lamp's
    ++dark;
    litY += global.tristimulus.pixels[3 * i + 1];
  }
  litY /= dark;
  std::printf("the lamp room: %d of %zu pixels dark under direct transport, their mean Y %.3f cd/m² under global\n",
              dark, direct.tristimulus.pixelCount(), litY);
  EXPECT_GE(dark, 185);
  EXPECT_GT(litY, 20.0);  // walls, floor and spheres
}

}  // namespace
}  // namespace prism::reference

// Closed-form checks of the lighting pass's maths through its CPU twin (shaders/shared/
// pixel_shading.glsl compiled as C++): a white Lambertian surface under a directional light of
// E lux has luminance E/π in every mode, conductors follow their normal-incidence Fresnel, and
// the display transform keeps colours finite and inside the gamut.
#include "render/cpu_shading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <numbers>

#include "core/error.h"
#include "render/display_transform.h"
#include "scene/scene_loader.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/table_test_support.h"
#include "techniques/prt/prt_section.h"
#include "techniques/underwater/water_section.h"

namespace prism::render {
namespace {

// Built once per build folder (PRISM_CACHE_DIR): RGB and spectral agree under the gamut's white
// only as well as the table reproduces its colours.
const RgbToSpectrumTable& productionTable() { return rendererRgbToSpectrumTable("srgb"); }

Scene oneLightScene(const std::string& spd, float lux) {
  Scene scene;
  scene.file = "test.json";
  Light light;
  light.type = LightType::Directional;
  light.direction = {0.0f, -1.0f, 0.0f};
  light.spd = illuminant(spd) * (1.0 / luminousIntegral(illuminant(spd)));
  light.intensity = lux;
  light.castsShadows = false;
  scene.lights.push_back(light);
  Material white;
  white.baseColour = glm::vec3(1.0f);
  white.lambertian = true;
  scene.materials.push_back(white);
  return scene;
}

// A texel of material 0 at the origin facing up, seen from straight above (`height` m up).
struct UpFacing {
  GBufferTexel texel;
  CameraTransform camera;
  UpFacing(const glm::vec3& albedo, float metallic, float roughness, float height = 2.0f) {
    texel.albedoMetallic = glm::vec4(albedo, metallic);
    texel.normalRoughness = glm::vec4(0.0f, 1.0f, 0.0f, roughness);
    texel.materialId = 1;
    Camera c;
    c.position = {0.0f, height, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    camera = cameraTransform(c, 64, 64);
    // The depth of the origin at the image centre.
    glm::vec4 clip = camera.viewProjection * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    texel.depth = clip.z / clip.w * 0.5f + 0.5f;
  }
};

glm::vec3 shadeOnce(const Scene& scene, const FrameSettings& settings, const UpFacing& p,
                    const RgbToSpectrumTable& lut = cachedTestTable()) {
  FrameData frame = buildFrameData(scene, settings, frameContext(settings, scene, lut), lut, {}, 0,
                                   cameraTransform(scene.camera, settings.width, settings.height));
  CpuShading shading(frame, lut, {});
  return shading.shade(p.texel, glm::vec2(0.5f), p.camera);
}

TEST(CpuShading, WhiteLambertianUnderDaylightHasLuminanceEOverPi) {
  Scene scene = oneLightScene("D65", 1000.0f);
  UpFacing p(glm::vec3(1.0f), 0.0f, 1.0f);
  const double expected = 1000.0 / 3.14159265358979;
  for (RenderMode mode : {RenderMode::Rgb, RenderMode::Naive, RenderMode::JakobHanika,
                          RenderMode::Reference}) {
    FrameSettings settings;
    settings.mode = mode;
    settings.sampling = {64, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Uniform};
    glm::vec3 xyz = shadeOnce(scene, settings, p);
    // RGB: exact by construction. Spectral: the upsampled white is 1 within the table's fit,
    // 64 midpoint samples of ∫ D65·ȳ are within 0.5 %, the reference's 472 within 0.1 %.
    double tolerance = mode == RenderMode::Rgb ? 1e-5 : mode == RenderMode::Reference ? 2e-3 : 1e-2;
    EXPECT_NEAR(xyz.y / expected, 1.0, tolerance) << renderModeName(mode);
  }
}

TEST(CpuShading, UnderTheColourSpacesWhiteSpectralLightingReproducesRgb) {
  // The upsampling table is fitted so that each albedo's spectrum, lit by the colour space's
  // white (D65 for sRGB), has that albedo's colour: a Lambertian surface under a D65 light must
  // then look the same in RGB mode and in the reference.
  Scene scene = oneLightScene("D65", 1000.0f);
  for (glm::vec3 albedo : {glm::vec3(0.5f, 0.2f, 0.1f), glm::vec3(0.1f, 0.6f, 0.3f),
                           glm::vec3(0.2f, 0.3f, 0.8f)}) {
    UpFacing p(albedo, 0.0f, 1.0f);
    FrameSettings rgb;
    rgb.mode = RenderMode::Rgb;
    FrameSettings reference;
    reference.mode = RenderMode::Reference;
    glm::vec3 a = shadeOnce(scene, rgb, p, productionTable());
    glm::vec3 b = shadeOnce(scene, reference, p, productionTable());
    EXPECT_NEAR(b.x / a.x, 1.0, 5e-3);
    EXPECT_NEAR(b.y / a.y, 1.0, 5e-3);
    EXPECT_NEAR(b.z / a.z, 1.0, 5e-3);
  }
}

// RGB mode carries a light as its colour in the scene's colour space; a 450 nm LED's is far
// outside sRGB (negative red and green), and lit a green albedo with Y −8 166 cd/m² (the
// reference 126). No tristimulus component is negative now; white shows the light as it is.
TEST(CpuShading, RgbModeLightsNothingWithNegativeLight) {
  Scene scene = oneLightScene("led:450:20", 10000.0f);
  FrameSettings rgb;
  rgb.mode = RenderMode::Rgb;
  for (glm::vec3 albedo : {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f),
                           glm::vec3(1.0f)}) {
    const glm::vec3 xyz = shadeOnce(scene, rgb, UpFacing(albedo, 0.0f, 1.0f), productionTable());
    EXPECT_GE(xyz.y, 0.0f) << albedo.x << " " << albedo.y << " " << albedo.z;
    EXPECT_GE(std::min(xyz.x, xyz.z), 0.0f);
  }
  // White shows the light's own colour and luminance, E/π: its tristimulus at 10 000 lux.
  const glm::vec3 white = shadeOnce(scene, rgb, UpFacing(glm::vec3(1.0f), 0.0f, 1.0f), productionTable());
  const Eigen::Vector3d light = luminousTristimulus(scene.lights[0].spd) * (10000.0 / 3.14159265358979);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c] / light[c], 1.0, 1e-4) << c;
}

// The lighting pass takes 16 lights; a sky's sun counts among them, and the error says so (a
// user's 16 lights and an atmosphere were refused as "17 lights", no place, no sun named).
TEST(FrameData, TheLightLimitNamesTheLightsATechniqueAdded) {
  Scene scene = oneLightScene("D65", 1000.0f);
  scene.file = "sky.json";
  while (scene.lights.size() < 16) scene.lights.push_back(scene.lights[0]);
  EXPECT_NO_THROW(requireLightCount(scene));
  Light sun = scene.lights[0];
  sun.technique = "atmosphere";
  scene.lights.push_back(sun);
  try {
    requireLightCount(scene);
    ADD_FAILURE() << "17 lights were taken";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "sky.json: /lights: 17 lights (16 in the file, and the atmosphere's sun); the renderer handles at most 16");
  }
}

TEST(CpuShading, NaiveUpsamplingOfGreyIsFlat) {
  // Box upsampling of a grey is that grey at every wavelength: Y = grey · E/π.
  Scene scene = oneLightScene("A", 500.0f);
  UpFacing p(glm::vec3(0.25f), 0.0f, 1.0f);
  FrameSettings settings;
  settings.mode = RenderMode::Naive;
  settings.sampling = {400, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Uniform};
  EXPECT_NEAR(shadeOnce(scene, settings, p).y, 0.25 * 500.0 / 3.14159265358979, 0.02);
}

TEST(CpuShading, ConductorAtNormalIncidenceReflectsItsFresnelReflectance) {
  // A mirror-like conductor lit and seen along its normal: the BRDF's D·G/(4·n·l·n·v) at
  // roughness r is known, so the ratio of a conductor to a metallic white (a measured
  // reflectance of exactly 1 as F0, so Schlick's F = 1) is the Fresnel reflectance
  // ((n−1)² + k²)/((n+1)² + k²), here for constant n, k.
  Scene scene = oneLightScene("D65", 1000.0f);
  scene.materials[0].lambertian = false;
  scene.materials[0].reflectance = Spectrum::constant(1.0);
  Material conductor;
  conductor.roughness = 0.3f;
  conductor.conductor = ConductorIor{"test", Spectrum::constant(0.5), Spectrum::constant(2.5)};
  scene.materials.push_back(conductor);
  UpFacing white(glm::vec3(1.0f), 1.0f, 0.3f);
  UpFacing metal(glm::vec3(1.0f), 1.0f, 0.3f);
  metal.texel.materialId = 2;
  FrameSettings settings;
  settings.sampling.count = 16;
  double ratio = shadeOnce(scene, settings, metal).y / shadeOnce(scene, settings, white).y;
  double expected = ((0.5 - 1) * (0.5 - 1) + 2.5 * 2.5) / ((0.5 + 1) * (0.5 + 1) + 2.5 * 2.5);
  EXPECT_NEAR(ratio, expected, 1e-4);
}

// Under water a distant environment in-scatters as the sun does (shared/underwater.glsl), with its
// radiance over the sky as E(0): looking level from depth z into open water under a uniform
// environment of radiance L, with no light, the background is σs·2πL·e^(−Kd·z)/(4π·σt) per
// wavelength — against that spectrum's 1 nm integral.
TEST(CpuShading, UnderWaterTheEnvironmentInScattersAsTheSunDoes) {
  Scene scene;
  scene.file = "test.json";
  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, -1.0f};
  scene.background = glm::vec3(0.0f);
  auto water = std::make_unique<underwater::WaterSection>();
  water->type.assign("IB");
  water->depthM = 3.0f;
  water->resolve();
  const underwater::WaterSection& w = *water;
  scene.techniques.add(std::move(water));
  auto environment = std::make_unique<prt::PrtSection>();
  environment->illuminant = "D65";
  environment->shape = "uniform";
  environment->luminanceCdM2 = 2000.0f;
  scene.techniques.add(std::move(environment));
  const auto sky = scene.techniques.find<prt::PrtSection>()->environment(productionTable());
  const Spectrum expected = Spectrum::fromFunction([&](double lambdaNm) {
    const double s = w.sigmaS.at(lambdaNm), t = s + w.sigmaA.at(lambdaNm);
    const double l = sky->radiance(glm::vec3(0.0f, 1.0f, 0.0f), lambdaNm);
    return s * 2.0 * std::numbers::pi * l * std::exp(-w.kd.at(lambdaNm) * 3.0) / (4.0 * std::numbers::pi * t);
  });
  const double luminance = luminousIntegral(expected);

  FrameSettings settings;
  settings.mode = RenderMode::Reference;
  const CameraTransform camera = cameraTransform(scene.camera, settings.width, settings.height);
  FrameData frame = buildFrameData(scene, settings, frameContext(settings, scene, productionTable()), productionTable(),
                                   {}, 0, camera);
  CpuShading shading(frame, productionTable(), {});
  const glm::vec3 background = shading.shade(GBufferTexel{}, glm::vec2(0.5f), camera);
  std::printf("level background under water: Y %.5g against %.5g\n", background.y, luminance);
  EXPECT_GT(luminance, 1.0);
  EXPECT_NEAR(background.y, luminance, 2e-3 * luminance);
}

// A lamp above the water lights a point below it through the water only on its path's lower part:
// at 10 m and at 100 m above the surface, its intensity scaled by the squared distance, the same
// point 2.5 m down shows the same (it was dimmed over the whole distance, e^(−σt·100 m): black).
// The water absorbs and scatters nothing into the view: the lamp's glow along the view ray, which
// does depend on its distance, is underwater_lamps_test's.
TEST(CpuShading, ALampAboveTheWaterIsDimmedOnlyBelowTheSurface) {
  Scene scene;
  scene.file = "test.json";
  Material white;
  white.baseColour = glm::vec3(1.0f);
  white.lambertian = true;
  scene.materials.push_back(white);
  UpFacing p(glm::vec3(1.0f), 0.0f, 1.0f);
  scene.camera.position = {0.0f, 2.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  auto water = std::make_unique<underwater::WaterSection>();
  water->type.assign("II");
  water->depthM = 0.5f;  // the camera's: the surface at y = 2.5, the lit point 2.5 m below it
  water->scatteringScale = 0.0f;
  water->resolve();
  scene.techniques.add(std::move(water));
  auto lit = [&](float heightAboveSurface, bool wet = true) {
    Scene s = scene;
    if (!wet) s.techniques.remove("water");
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {0.0f, 2.5f + heightAboveSurface, 0.0f};
    lamp.spd = illuminant("A") * (1.0 / luminousIntegral(illuminant("A")));
    const float distance = lamp.position.y / 12.5f;
    lamp.intensity = 1000.0f * distance * distance;
    lamp.castsShadows = false;
    s.lights.push_back(lamp);
    FrameSettings settings;
    settings.mode = RenderMode::Reference;
    return shadeOnce(s, settings, p, productionTable());
  };
  const glm::vec3 near = lit(10.0f), far = lit(100.0f), dry = lit(10.0f, false);
  std::printf("a lamp 10 m / 100 m above the water, 2.5 m below it: Y %.6g / %.6g (dry %.6g)\n", near.y, far.y, dry.y);
  // Dimmed through 2.5 m of water down and 2 m up (Jerlov II), yet not black; just above the
  // surface as just below it (its light crosses the same 2.5 m of water).
  EXPECT_LT(near.y, 0.8f * dry.y);
  EXPECT_GT(near.y, 0.05f * dry.y);
  const glm::vec3 justAbove = lit(0.01f), justBelow = lit(-0.01f);
  EXPECT_NEAR(justAbove.y, justBelow.y, 0.01f * justBelow.y);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(far[c], near[c], 1e-4f * near[c]) << c;
}

// The viewer's camera can fly above the water: the air between it and the surface is clear, so
// the sea floor 2 m down and the open ocean (the background, looking down) look the same from 1 m
// and 10 m above the surface as from the surface itself, in-scattering of the sun and of a lamp
// and a spot under water included; just below the surface they look nearly so. (The air was
// taken for water: from 10 m up, 12 m of it.)
// Jerlov II, its surface at y = 2 (the scene's camera 1 m below it), the sun, and a point lamp and a
// spot under water beside the origin, the spot's beam across the view from above.
Scene sunAndLampsUnderWater() {
  Scene scene = oneLightScene("D65", 1000.0f);
  scene.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  Light lamp;
  lamp.type = LightType::Point;
  lamp.position = {0.5f, 1.0f, 0.3f};
  lamp.spd = illuminant("A") * (1.0 / luminousIntegral(illuminant("A")));
  lamp.intensity = 50.0f;
  lamp.castsShadows = false;
  scene.lights.push_back(lamp);
  lamp.type = LightType::Spot;
  lamp.position = {-1.0f, 1.5f, 0.0f};
  lamp.direction = glm::normalize(glm::vec3(1.0f, -0.2f, 0.0f));  // its beam across the view
  lamp.innerConeDeg = 10.0f;
  lamp.outerConeDeg = 15.0f;
  scene.lights.push_back(lamp);
  scene.camera.position = {0.0f, 1.0f, 0.0f};
  auto water = std::make_unique<underwater::WaterSection>();
  water->type.assign("II");
  water->depthM = 1.0f;  // the scene camera's: the surface at y = 2
  water->resolve();
  scene.techniques.add(std::move(water));
  return scene;
}

TEST(CpuShading, ACameraAboveTheWaterSeesThroughClearAir) {
  const Scene scene = sunAndLampsUnderWater();
  FrameSettings settings;
  settings.mode = RenderMode::Reference;
  auto seenFrom = [&](float height) {
    const UpFacing p(glm::vec3(0.8f), 0.0f, 1.0f, height);
    FrameData frame = buildFrameData(scene, settings, frameContext(settings, scene, productionTable()),
                                     productionTable(), {}, 0, p.camera);
    CpuShading shading(frame, productionTable(), {});
    return std::pair{shading.shade(p.texel, glm::vec2(0.5f), p.camera),
                     shading.shade(GBufferTexel{}, glm::vec2(0.5f), p.camera)};
  };
  const auto [floor, ocean] = seenFrom(2.0f);
  for (float height : {3.0f, 12.0f, 1.999f}) {
    const auto [floorThere, oceanThere] = seenFrom(height);
    std::printf("from %g m: the floor Y %.6g (%.6g from the surface), the ocean Y %.6g (%.6g)\n", height,
                floorThere.y, floor.y, oceanThere.y, ocean.y);
    const float tolerance = height < 2.0f ? 2e-3f : 1e-4f;  // 1 mm of water
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(floorThere[c], floor[c], tolerance * floor[c]) << height << " m, " << c;
      EXPECT_NEAR(oceanThere[c], ocean[c], tolerance * ocean[c]) << height << " m, " << c;
    }
  }
}

// The water's lamp_scattering off leaves the lamps' glow and beam out of the view (for speed) and
// nothing else: the open ocean below the camera shows what it shows without the lamps, and the
// floor what their light on it alone adds.
TEST(CpuShading, LampsScatterIntoTheViewUnlessTheWaterSaysNot) {
  const Scene scene = sunAndLampsUnderWater();
  FrameSettings settings;
  settings.mode = RenderMode::Reference;
  auto seen = [&](const Scene& s) {
    const UpFacing p(glm::vec3(0.8f), 0.0f, 1.0f, 1.5f);  // half a metre under the surface
    FrameData frame = buildFrameData(s, settings, frameContext(settings, s, productionTable()), productionTable(), {},
                                     0, p.camera);
    CpuShading shading(frame, productionTable(), {});
    return std::pair{shading.shade(p.texel, glm::vec2(0.5f), p.camera),
                     shading.shade(GBufferTexel{}, glm::vec2(0.5f), p.camera)};
  };
  Scene unscattered = scene, sunOnly = scene;
  unscattered.techniques.find<underwater::WaterSection>()->lampScattering = false;
  sunOnly.lights.resize(1);
  const auto [floor, ocean] = seen(scene);
  const auto [floorUnscattered, oceanUnscattered] = seen(unscattered);
  const auto [floorSunOnly, oceanSunOnly] = seen(sunOnly);
  std::printf("the ocean's Y: %.6g with the lamps' glow, %.6g without, %.6g without the lamps\n", ocean.y,
              oceanUnscattered.y, oceanSunOnly.y);
  EXPECT_GT(ocean.y, 1.05f * oceanUnscattered.y);
  EXPECT_GT(floor.y, floorUnscattered.y);
  EXPECT_GT(floorUnscattered.y, 1.01f * floorSunOnly.y);  // the lamp 1 m above it adds 2 %
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(oceanUnscattered[c], oceanSunOnly[c], 1e-6f * oceanSunOnly[c]) << c;
}

// The lamps' glow is worked out for four batches of wavelengths at a time, the rest one by one
// (lampsInWater): over 360–830 nm it must be the sum of the glows of the same wavelengths taken
// four at a time in their own frames, one batch each (16 wavelengths in one group of four; 20 in a
// group and one more; 32 in two groups), whatever slip the grouping made in both twins alike.
TEST(CpuShading, TheLampsGlowIsTheSumOfItsBatches) {
  const Scene scene = sunAndLampsUnderWater();
  Scene unscattered = scene;
  unscattered.techniques.find<underwater::WaterSection>()->lampScattering = false;
  const UpFacing p(glm::vec3(0.8f), 0.0f, 1.0f, 1.5f);
  auto glow = [&](int count, double minNm, double maxNm) {
    FrameSettings settings;
    settings.mode = RenderMode::JakobHanika;
    settings.sampling.count = count;
    settings.sampling.minNm = minNm;
    settings.sampling.maxNm = maxNm;
    settings.sampling.strategy = SamplingStrategy::Uniform;
    auto background = [&](const Scene& s) {
      FrameData frame = buildFrameData(s, settings, frameContext(settings, s, productionTable()), productionTable(),
                                       {}, 0, p.camera);
      return glm::dvec3(CpuShading(frame, productionTable(), {}).shade(GBufferTexel{}, glm::vec2(0.5f), p.camera));
    };
    return background(scene) - background(unscattered);
  };
  for (int count : {16, 20, 32}) {
    const glm::dvec3 whole = glow(count, 360.0, 830.0);
    glm::dvec3 parts(0.0);
    const double step = 470.0 / count * 4.0;
    for (int k = 0; k < count / 4; ++k) parts += glow(4, 360.0 + k * step, 360.0 + (k + 1) * step);
    std::printf("%d wavelengths: the glow's Y %.6g, its batches' %.6g\n", count, whole.y, parts.y);
    ASSERT_GT(whole.y, 0.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(whole[c], parts[c], 1e-5 * whole.y) << count << " wavelengths, " << c;
  }
}

TEST(Brdf, ConductorFresnelAtOneAngleMatchesTheComplexFresnelEquations) {
  // Rs and Rp from the complex index η = n + ik in double precision (Born & Wolf), at 0°, 45°,
  // 60° and 85°: the closed form in brdf.glsl must agree, oblique angles included (at normal
  // incidence Rs = Rp, which leaves half the formula untested).
  const double n = 0.27, k = 2.78;  // gold near 550 nm
  for (double degrees : {0.0, 45.0, 60.0, 85.0}) {
    double c = std::cos(degrees * 3.14159265358979 / 180.0);
    std::complex<double> eta(n, k);
    std::complex<double> cosT = std::sqrt(1.0 - (1.0 - c * c) / (eta * eta));
    double rs = std::norm((c - eta * cosT) / (c + eta * cosT));
    double rp = std::norm((eta * c - cosT) / (eta * c + cosT));
    glm::vec4 f = shared::conductorFresnel(glm::vec4(static_cast<float>(n)),
                                           glm::vec4(static_cast<float>(k)), static_cast<float>(c));
    EXPECT_NEAR(f.x, 0.5 * (rs + rp), 2e-5) << degrees << "°";
  }
}

TEST(CpuShading, BackfacingLightGivesNothing) {
  Scene scene = oneLightScene("D65", 1000.0f);
  scene.lights[0].direction = {0.0f, 1.0f, 0.0f};  // travelling up, from below the surface
  UpFacing p(glm::vec3(0.8f), 0.0f, 0.5f);
  FrameSettings settings;
  glm::vec3 xyz = shadeOnce(scene, settings, p);
  EXPECT_EQ(xyz, glm::vec3(0.0f));
}

TEST(DisplayTransform, OutOfGamutColoursAreCompressedNotClippedToNaN) {
  const glm::vec3 weights(0.2126f, 0.7152f, 0.0722f);
  for (glm::vec3 rgb : {glm::vec3(-0.2f, 0.5f, 0.1f), glm::vec3(1.5f, -0.3f, -0.1f),
                        glm::vec3(-1.0f, -1.0f, -1.0f), glm::vec3(0.0f)}) {
    glm::vec3 out = shared::compressToGamut(rgb, weights);
    EXPECT_GE(std::min({out.x, out.y, out.z}), -1e-6f);
    EXPECT_FALSE(std::isnan(out.x) || std::isnan(out.y) || std::isnan(out.z));
    float y = glm::dot(rgb, weights);
    if (y > 0.0f) {
      EXPECT_NEAR(glm::dot(out, weights), y, 1e-6f);
    }
  }
  glm::vec3 inside(0.2f, 0.3f, 0.4f);
  EXPECT_EQ(shared::compressToGamut(inside, weights), inside);
}

TEST(DisplayTransform, ExposureMapsTheSaturationLuminanceToWhite) {
  DisplaySettings settings;
  settings.ev100 = 10.0f;
  DisplayTransform t = displayTransform(settings, resolveDisplay(settings, observer("cie1931")), 0.0f);
  // D65 white of luminance 1.2·2^10 cd/m² → display RGB (1, 1, 1).
  glm::vec3 d65(0.95047f, 1.0f, 1.08883f);
  glm::vec3 rgb = t.toDisplay * (d65 * 1.2f * 1024.0f);
  EXPECT_NEAR(rgb.x, 1.0f, 2e-3f);
  EXPECT_NEAR(rgb.y, 1.0f, 2e-3f);
  EXPECT_NEAR(rgb.z, 1.0f, 2e-3f);
}

// However overexposed, a bright neutral pixel shows white, never black: ACES's x² overflowed float to
// ∞/∞ = NaN at EV −70, and an exposure whose product overflows is as bright as a pixel gets.
TEST(DisplayTransform, ExtremeOverexposureShowsWhiteUnderEveryToneMap) {
  DisplaySettings settings;
  const DisplayTransform srgb = displayTransform(settings, resolveDisplay(settings, cie1931Observer()), 0.0f);
  for (int op : {shared::kToneMapNone, shared::kToneMapReinhard, shared::kToneMapAces}) {
    for (float exposure : {std::exp2(70.0f), 1e30f}) {
      glm::vec3 rgb = shared::encodeForDisplay(glm::mat3(exposure), srgb.displayToXyz, srgb.xyzToDisplay, op, 0,
                                               glm::vec3(1e10f));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0f, 1e-3f) << "tone map " << op << ", exposure " << exposure;
    }
  }
}

// Issue 16: the blue LED's wall (scenes/spheres_blue_led.json) showed magenta once its blue
// clipped under ACES while its red kept growing. Its displayed CIELAB hue — an 8-bit sRGB pixel
// decoded again — stays within 10° of the light's own from 4 EV under to 4 EV over the exposure
// that puts it at display white; per channel it drifted 20° (307.5° to 327.9°, the light 316.7°).
TEST(DisplayTransform, OverexposedNarrowBandLightKeepsItsHue) {
  const Eigen::Vector3d led = cie1931Observer().integrate(illuminant("led:450:20"));
  const glm::vec3 xyz = glm::vec3(static_cast<float>(led.x()), static_cast<float>(led.y()),
                                  static_cast<float>(led.z())) /
                        static_cast<float>(led.y());
  DisplaySettings settings;
  const DisplayTransform srgb = displayTransform(settings, resolveDisplay(settings, cie1931Observer()), 0.0f);
  const glm::vec3 white = srgb.displayToXyz * glm::vec3(1.0f);
  auto hueDeg = [&](const glm::vec3& xyzValue) {
    glm::vec3 lab = shared::xyzToLab(xyzValue, white);
    return std::atan2(lab.z, lab.y) * 180.0f / 3.14159265f;
  };
  const float own = hueDeg(xyz);
  for (int offset = -4; offset <= 4; ++offset) {
    settings.ev100 = static_cast<float>(-offset);  // one EV less of exposure value: twice the light
    DisplayTransform t = displayTransform(settings, resolveDisplay(settings, cie1931Observer()), 0.0f);
    glm::vec3 scene = xyz * static_cast<float>(displayWhiteLuminance(0.0f));  // display white at offset 0
    glm::vec3 encoded = encodeForDisplay(t, ToneMap::Aces, scene);
    glm::vec3 shown = glm::round(encoded * 255.0f) / 255.0f;
    float hue = hueDeg(srgb.displayToXyz * shared::srgbDecode3(shown));
    float difference = std::abs(std::remainder(hue - own, 360.0f));
    EXPECT_LE(difference, 10.0f) << "at " << offset << " EV: hue " << hue << "°, the light's " << own << "°, shown "
                                 << shown.x * 255 << ", " << shown.y * 255 << ", " << shown.z * 255;
  }
}

TEST(DisplayTransform, WhiteBalanceMakesTheIlluminantNeutral) {
  DisplaySettings settings;
  settings.ev100 = 0.0f;
  settings.whiteBalance = "A";
  DisplayTransform t = displayTransform(settings, resolveDisplay(settings, observer("cie1931")), 0.0f);
  Eigen::Vector3d a = observer("cie1931").integrate(illuminant("A"));
  glm::vec3 xyz(static_cast<float>(a.x() / a.y()), 1.0f, static_cast<float>(a.z() / a.y()));
  glm::vec3 rgb = t.toDisplay * xyz;
  EXPECT_NEAR(rgb.x / rgb.y, 1.0f, 1e-3f);
  EXPECT_NEAR(rgb.z / rgb.y, 1.0f, 1e-3f);
}

}  // namespace
}  // namespace prism::render

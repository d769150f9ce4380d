// The reference held to closed forms: a white furnace, a Lambertian plane and a sphere under a
// directional light, the error's fall with the sample count, and determinism. Tolerances on
// noisy estimates come from the renderer's own variance image (z-scores), not from guesses.
#include "reference/path_tracer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/worst_of.h"
#include "reference/path_tracer_test_support.h"
#include "scene/camera_transform.h"
#include "scene/procedural_mesh.h"
#include "scene/scene_loader.h"
#include "scene/scene_spectra.h"
#include "core/error.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "techniques/underwater/water_section.h"

namespace prism::reference {
namespace {

constexpr double kPi = 3.14159265358979;

const RgbToSpectrumTable& srgbTable() { return rendererRgbToSpectrumTable("srgb"); }

Light directionalLight(const glm::vec3& direction, float lux, const char* spd = "D65") {
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(direction);
  light.spd = illuminant(spd);
  light.spd *= 1.0 / luminousIntegral(light.spd);
  light.intensity = lux;
  return light;
}

Material constantReflectance(double rho) {
  Material m;
  m.lambertian = true;
  m.reflectance = Spectrum::constant(rho);
  return m;
}

// XYZ / Y of a normalised illuminant (the chromaticity every pixel of a grey surface under it has).
Eigen::Vector3d perLuminance(const char* spd = "D65") {
  Eigen::Vector3d xyz = observer("cie1931").integrate(illuminant(spd));
  return xyz / xyz.y();
}

// A plane filling the view, lit at cos θ = 0.6.
Scene litPlane(double rho, float lux, const char* spd = "D65") {
  Scene scene;
  scene.camera.position = {0.0f, 3.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.verticalFovDeg = 30.0f;
  scene.lights.push_back(directionalLight({0.8f, -0.6f, 0.0f}, lux, spd));
  scene.materials.push_back(constantReflectance(rho));
  scene.meshes.push_back(makePlane({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {20.0f, 20.0f}));
  return scene;
}

ReferenceSettings small(int spp) {
  ReferenceSettings s;
  s.width = 48;
  s.height = 32;
  s.samplesPerPixel = spp;
  s.filter = PixelFilter::Centre;
  return s;
}

// A flat image against its closed form: the largest |z| of any pixel's channel (from the
// variance image), the mean over pixels, and the mean variance of Y's estimate.
struct PlaneCheck {
  double worstZ = 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double meanVariance = 0.0;  // Y
};
PlaneCheck checkPlane(const ReferenceImage& image, const Eigen::Vector3d& expected) {
  PlaneCheck check;
  for (std::size_t i = 0; i < image.tristimulus.pixelCount(); ++i) {
    for (int c = 0; c < 3; ++c) {
      double v = image.tristimulus.pixels[3 * i + static_cast<std::size_t>(c)];
      double sigma = std::sqrt(image.variance.pixels[3 * i + static_cast<std::size_t>(c)]);
      check.mean[c] += v;
      check.worstZ = std::max(check.worstZ, std::abs(v - expected[c]) / std::max(sigma, 1e-6 * expected[c]));
    }
    check.meanVariance += image.variance.pixels[3 * i + 1];
  }
  check.mean /= static_cast<double>(image.tristimulus.pixelCount());
  check.meanVariance /= static_cast<double>(image.tristimulus.pixelCount());
  return check;
}

TEST(PathTracer, LambertianPlaneUnderADirectionalLightIsRhoECosOverPi) {
  Scene scene = litPlane(0.5, 1000.0f);
  ReferenceImage image = renderReference(scene, srgbTable(), small(16));
  const Eigen::Vector3d expected = perLuminance() * (0.5 * 1000.0 * 0.6 / kPi);
  PlaneCheck check = checkPlane(image, expected);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(check.mean[c] / expected[c], 1.0, 2e-3) << "channel " << c;
  // 1536 pixels × 3 channels: |z| beyond 5 has odds of 1e-6 each for a correct estimator (and
  // the sample variance over-estimates a stratified mean's, so real z-scores are smaller).
  EXPECT_LT(check.worstZ, 5.0);
}

TEST(PathTracer, TheDefaultLightsPdfIsUnbiasedAndQuieterUnderASpikyLamp) {
  // The same plane under F11, hero wavelengths drawn by default from the lights' pdf (the
  // rasteriser's): still ρ·E·cos θ/π, and with the pdf ∝ F11·Σ c̄/∫F11·c̄ only the smooth ratio
  // of c̄ to that sum is left to the samples, so the variance falls far below Importance's, which
  // must find F11's lines (measured 27× below; ask for 10×).
  Scene scene = litPlane(0.5, 1000.0f, "F11");
  const Eigen::Vector3d expected = perLuminance("F11") * (0.5 * 1000.0 * 0.6 / kPi);
  ReferenceSettings settings = small(16);
  PlaneCheck lights = checkPlane(renderReference(scene, srgbTable(), settings), expected);
  settings.wavelengths.strategy = SamplingStrategy::Importance;
  PlaneCheck importance = checkPlane(renderReference(scene, srgbTable(), settings), expected);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(lights.mean[c] / expected[c], 1.0, 2e-3) << "channel " << c;
  EXPECT_LT(lights.worstZ, 5.0);  // as above
  std::printf("variance of Y's mean under F11: lights %.3g, importance %.3g\n", lights.meanVariance,
              importance.meanVariance);
  EXPECT_LT(lights.meanVariance, importance.meanVariance / 10.0);
}

// A table of another colour space than the scene's is the caller's error, said as the renderer
// says it (the tracer aborted on an internal check).
TEST(PathTracer, RefusesAnUpsamplingTableOfAnotherColourSpace) {
  Scene scene = litPlane(0.5, 1000.0f);
  scene.colourSpace = "rec2020";
  scene.file = "plane.json";
  try {
    renderReference(scene, srgbTable(), small(1));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "plane.json: the upsampling table is for srgb, the scene is in rec2020");
  }
}

TEST(PathTracer, LambertianSphereUnderADirectionalLightMatchesTheClosedFormPerPixel) {
  Scene scene;
  scene.camera.position = {0.0f, 0.0f, 4.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.verticalFovDeg = 35.0f;
  const glm::vec3 toLight = glm::normalize(glm::vec3(0.5f, 0.7f, 0.5f));
  scene.lights.push_back(directionalLight(-toLight, 2000.0f));
  scene.materials.push_back(constantReflectance(0.8));
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 1.0f, 256));
  ReferenceSettings settings = small(16);
  settings.width = settings.height = 64;
  ReferenceImage image = renderReference(scene, srgbTable(), settings);

  // The ideal sphere seen through each pixel centre: Y = ρ·E·max(0, n·l)/π.
  CameraTransform camera = cameraTransform(scene.camera, settings.width, settings.height);
  double sumError = 0.0, maxError = 0.0;
  int count = 0;
  const float w = static_cast<float>(settings.width), h = static_cast<float>(settings.height);
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      float u = (static_cast<float>(x) + 0.5f) / w, v = 1.0f - (static_cast<float>(y) + 0.5f) / h;
      glm::vec4 far = camera.inverseViewProjection * glm::vec4(u * 2.0f - 1.0f, v * 2.0f - 1.0f, 1.0f, 1.0f);
      glm::vec3 d = glm::normalize(glm::vec3(far) / far.w - camera.position);
      glm::vec3 o = camera.position;
      float b = glm::dot(o, d), c = glm::dot(o, o) - 1.0f, disc = b * b - c;
      if (disc < 0.05f) continue;  // off the sphere, or grazing its tessellated rim
      glm::vec3 n = glm::normalize(o + d * (-b - std::sqrt(disc)));
      double expected = 0.8 * 2000.0 * std::max(0.0f, glm::dot(n, toLight)) / kPi;
      double got = image.tristimulus.at(x, y, 1);
      double error = std::abs(got - expected) / (0.8 * 2000.0 / kPi);
      sumError += error;
      maxError = std::max(maxError, error);
      ++count;
    }
  }
  ASSERT_GT(count, 1000);
  // Against the peak: 256 segments place facets within 8e-5 of the sphere and interpolated
  // normals within 0.1° of its own; the rest is wavelength noise (a few 1e-3 per pixel).
  EXPECT_LT(sumError / count, 2e-3);
  EXPECT_LT(maxError, 2e-2);
}

// A technique's distant light (TechniqueEnvironment): D65 of luminance `luminance` cd/m² from
// above, weighted by the direction's height, max(0, ω·y) — none from below.
class SkyFromAbove final : public TechniqueSection {
 public:
  explicit SkyFromAbove(double luminance) : mLuminance(luminance) {}
  std::string_view key() const override { return "sky_from_above"; }
  std::string_view shaderDefine() const override { return "PRISM_TECHNIQUE_SKY_FROM_ABOVE"; }
  std::unique_ptr<TechniqueSection> clone() const override { return std::make_unique<SkyFromAbove>(*this); }
  TechniqueBlock pack(const FramePackInput&) const override { return {}; }
  bool shadesObjects() const override { return true; }
  std::shared_ptr<const TechniqueEnvironment> environment(const RgbToSpectrumTable&) const override {
    struct Radiance final : TechniqueEnvironment {
      Spectrum spd;
      double radiance(const glm::vec3& d, double lambdaNm) const override { return std::max(0.0f, d.y) * spd.at(lambdaNm); }
    };
    auto e = std::make_shared<Radiance>();
    e->spd = illuminant("D65");
    e->spd *= mLuminance / luminousIntegral(e->spd);
    return e;
  }

 private:
  double mLuminance;
};

TEST(PathTracer, ATechniquesEnvironmentLightsItsObjectsAsLambertian) {
  // The plane of litPlane facing up, without the light, under L(ω) = L·max(0, ω·y): irradiance
  // ∫ L cos²θ dω = 2πL/3, so Y = ρ·(2πL/3)/π = 2ρL/3. Its material is Cook–Torrance, but a
  // technique shades it: traced as Lambertian. Direct transport samples the environment once
  // per surface point; global transport gathers it where paths leave the scene; the camera
  // sees neither (the background, black here: the plane fills the view anyway).
  Scene scene = litPlane(0.5, 1000.0f);
  scene.lights.clear();
  scene.materials[0].lambertian = false;
  scene.meshes[0].technique = "sky_from_above";
  scene.techniques.add(std::make_unique<SkyFromAbove>(600.0));
  const Eigen::Vector3d expected = perLuminance() * (2.0 * 0.5 * 600.0 / 3.0);
  for (LightTransport transport : {LightTransport::Direct, LightTransport::Global}) {
    // 256 paths a pixel: each pixel's variance is estimated from its own samples (unstratified
    // directions), which at 64 is itself too noisy for a z-score bound over 4 608 values.
    ReferenceSettings settings = small(256);
    settings.transport = transport;
    PlaneCheck check = checkPlane(renderReference(scene, srgbTable(), settings), expected);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(check.mean[c] / expected[c], 1.0, 2e-3) << "channel " << c;
    EXPECT_LT(check.worstZ, 5.0);  // as in the plane under a directional light
  }
}

TEST(PathTracer, WhiteFurnaceReturnsTheSurroundingRadianceEverywhere) {
  Scene scene;
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.materials.push_back(constantReflectance(1.0));
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 1.0f, 64));
  scene.background = glm::vec3(1.0f);
  scene.backgroundLuminance = 100.0f;
  ReferenceSettings settings = small(16);
  settings.transport = LightTransport::Global;
  settings.filter = PixelFilter::Box;
  ReferenceImage image = renderReference(scene, srgbTable(), settings);

  RgbIlluminantSpectrum background = backgroundRadiance(scene, colourSpace(scene.colourSpace), srgbTable());
  Spectrum b = Spectrum::fromFunction([&](double l) { return background.at(l); });
  Eigen::Vector3d expected = absoluteTristimulusScale(observer("cie1931")) * observer("cie1931").integrate(b);
  ASSERT_NEAR(expected.y(), 100.0, 0.1);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < image.tristimulus.pixelCount(); ++i) {
    for (int c = 0; c < 3; ++c) mean[c] += image.tristimulus.pixels[3 * i + static_cast<std::size_t>(c)];
  }
  mean /= static_cast<double>(image.tristimulus.pixelCount());
  // A sphere of albedo 1 neither absorbs nor emits: the image is the background, sphere or not.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c] / expected[c], 1.0, 3e-3) << "channel " << c;
}

// The white furnace with an emitting sphere: under global transport every path that meets it
// gathers its emission and then the background (albedo 1), so each pixel of it is L_e + L_b and
// every other pixel L_b; under direct transport, with no background, it is L_e alone.
TEST(PathTracer, AnEmittingSurfaceAddsItsRadianceToWhatItReflects) {
  Scene scene;
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  Material emitter = constantReflectance(1.0);
  Spectrum d65 = illuminant("D65");
  emitter.emission = Emission{d65 * (1.0 / luminousIntegral(d65)), 50.0f};
  scene.materials.push_back(emitter);
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 1.0f, 64));
  scene.background = glm::vec3(1.0f);  // D65 in sRGB: the emission's chromaticity
  for (const bool global : {true, false}) {
    scene.backgroundLuminance = global ? 100.0f : 0.0f;
    ReferenceSettings settings = small(16);
    settings.transport = global ? LightTransport::Global : LightTransport::Direct;
    ReferenceImage image = renderReference(scene, srgbTable(), settings);
    const double background = scene.backgroundLuminance, sphere = background + 50.0;
    // Each pixel's Y against its closed form, in units of its own standard error (the variance
    // image), and the sphere's mean.
    int onSphere = 0;
    double worstZ = 0.0, sphereMean = 0.0;
    for (std::size_t i = 0; i < image.tristimulus.pixelCount(); ++i) {
      const double y = image.tristimulus.pixels[3 * i + 1];
      const bool hit = y > background + 25.0;
      const double expected = hit ? sphere : background;
      const double sigma = std::max(std::sqrt(static_cast<double>(image.variance.pixels[3 * i + 1])), 1e-6 * sphere);
      worstZ = std::max(worstZ, std::abs(y - expected) / sigma);
      onSphere += hit ? 1 : 0;
      sphereMean += hit ? y : 0.0;
    }
    sphereMean /= onSphere;
    std::printf("%s: %d of %zu pixels on the sphere, mean Y %.3f (expected %.0f), worst |z| %.2f\n",
                global ? "global" : "direct", onSphere, image.tristimulus.pixelCount(), sphereMean, sphere, worstZ);
    EXPECT_GT(onSphere, 200) << global;
    EXPECT_NEAR(sphereMean / sphere, 1.0, 3e-3) << global;  // as the white furnace's mean
    EXPECT_LT(worstZ, 5.0) << global;
  }
}

// An emitter lights what sees it under global transport: a floor of albedo ρ inside a black
// sphere that emits L_e all round sees L_e over its whole sky, irradiance π·L_e, so its radiance
// is ρ·L_e; under direct transport, which aims only at the lights (none here), it is black.
TEST(PathTracer, UnderGlobalTransportAnEmitterLightsWhatSeesIt) {
  Scene scene = test::floorSeenFromAbove(constantReflectance(0.5));
  scene.materials.push_back(test::d65Emitter(40.0f));
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 100.0f, 64));
  scene.meshes.back().material = 1;
  for (const bool global : {true, false}) {
    ReferenceSettings settings = small(64);
    settings.transport = global ? LightTransport::Global : LightTransport::Direct;
    const Eigen::Vector3d expected = (global ? 0.5 * 40.0 : 0.0) * perLuminance();
    PlaneCheck check = checkPlane(renderReference(scene, srgbTable(), settings), expected);
    std::printf("%s: floor mean Y %.4f (expected %.1f), worst |z| %.2f\n", global ? "global" : "direct", check.mean.y(),
                expected.y(), check.worstZ);
    EXPECT_NEAR(check.mean.y(), expected.y(), 3e-3 * 20.0) << global;
    if (global) EXPECT_LT(check.worstZ, 5.0);  // as in the plane under a directional light
  }
}

TEST(PathTracer, ErrorFallsAtLeastAsOneOverRootSamples) {
  Scene scene = litPlane(0.5, 1000.0f);
  const double expectedY = 0.5 * 1000.0 * 0.6 / kPi;
  auto rms = [&](int spp) {
    ReferenceImage image = renderReference(scene, srgbTable(), small(spp));
    double sum = 0.0;
    for (std::size_t i = 0; i < image.tristimulus.pixelCount(); ++i) {
      double e = image.tristimulus.pixels[3 * i + 1] / expectedY - 1.0;
      sum += e * e;
    }
    return std::sqrt(sum / static_cast<double>(image.tristimulus.pixelCount()));
  };
  double rms4 = rms(4), rms64 = rms(64);
  // 1/√spp predicts 4×; the paths' stratified wavelengths do better than independent ones.
  EXPECT_GT(rms4 / rms64, 4.0 * 0.8) << "rms at 4 spp " << rms4 << ", at 64 spp " << rms64;
  EXPECT_GT(rms64, 0.0);
}

TEST(PathTracer, TheImageDependsOnTheSeedNotOnTheThreadCount) {
  Scene scene = litPlane(0.5, 1000.0f);
  ReferenceSettings settings = small(4);
  settings.transport = LightTransport::Global;
  settings.filter = PixelFilter::Box;
  settings.threads = 1;
  ReferenceImage one = renderReference(scene, srgbTable(), settings);
  settings.threads = 3;
  ReferenceImage three = renderReference(scene, srgbTable(), settings);
  EXPECT_EQ(one.tristimulus.pixels, three.tristimulus.pixels);
  settings.seed = 7;
  ReferenceImage other = renderReference(scene, srgbTable(), settings);
  EXPECT_NE(one.tristimulus.pixels, other.tristimulus.pixels);
}

// A region is the same paths as the whole image: its rows bit for bit, and its sample ranges'
// means weighted by their counts (plus their residuals) give the whole image's mean.
TEST(PathTracer, ARegionTracesTheWholeImagesPaths) {
  Scene scene = litPlane(0.5, 1000.0f);
  ReferenceSettings settings = small(12);
  settings.transport = LightTransport::Global;
  settings.filter = PixelFilter::Box;
  ReferenceImage whole = renderReference(scene, srgbTable(), settings);
  ReferenceImage band = renderReference(scene, srgbTable(), settings, {10, 17, 0, 12});
  ASSERT_EQ(band.tristimulus.height, 7);
  for (int y = 0; y < 7; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(band.tristimulus.at(x, y, c), whole.tristimulus.at(x, y + 10, c));
        ASSERT_EQ(band.variance.at(x, y, c), whole.variance.at(x, y + 10, c));
      }
    }
  }
  ReferenceImage first = renderReference(scene, srgbTable(), settings, {0, 32, 0, 5});
  ReferenceImage rest = renderReference(scene, srgbTable(), settings, {0, 32, 5, 12});
  for (std::size_t k = 0; k < whole.tristimulus.pixels.size(); ++k) {
    double a = double{first.tristimulus.pixels[k]} + first.meanResidual.pixels[k];
    double b = double{rest.tristimulus.pixels[k]} + rest.meanResidual.pixels[k];
    double merged = (5.0 * a + 7.0 * b) / 12.0;
    ASSERT_NEAR(merged, whole.tristimulus.pixels[k], 1e-7 * std::abs(whole.tristimulus.pixels[k])) << k;
  }
  EXPECT_THROW(renderReference(scene, srgbTable(), settings, {0, 32, 5, 13}), Error);
  EXPECT_THROW(renderReference(scene, srgbTable(), settings, {8, 8, 0, 12}), Error);
}

// Seen and lit through an absorbing slab: Beer–Lambert on both legs, per pixel.
TEST(PathTracer, AnAbsorbingSlabAttenuatesBothLegsByBeerLambert) {
  Scene scene = litPlane(0.5, 1000.0f);
  HomogeneousMedium slab;
  slab.sigmaA = Spectrum::constant(0.7);
  slab.sigmaS = Spectrum::constant(0.0);
  slab.region = Bounds{{-100.0f, 0.5f, -100.0f}, {100.0f, 1.5f, 100.0f}};
  scene.medium = slab;
  ReferenceSettings settings = small(8);
  ReferenceImage image = renderReference(scene, srgbTable(), settings);
  CameraTransform camera = cameraTransform(scene.camera, settings.width, settings.height);
  const float w = static_cast<float>(settings.width), h = static_cast<float>(settings.height);
  double worstZ = 0.0, meanRatio = 0.0;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      float u = (static_cast<float>(x) + 0.5f) / w, v = 1.0f - (static_cast<float>(y) + 0.5f) / h;
      glm::vec4 far = camera.inverseViewProjection * glm::vec4(u * 2.0f - 1.0f, v * 2.0f - 1.0f, 1.0f, 1.0f);
      glm::vec3 d = glm::normalize(glm::vec3(far) / far.w - camera.position);
      // 1 m of slab: 1/0.6 m along the light, 1/|d_y| m along the view.
      double expected = 0.5 * 1000.0 * 0.6 / kPi * std::exp(-0.7 / 0.6) * std::exp(-0.7 / std::abs(d.y));
      double sigma = std::sqrt(image.variance.at(x, y, 1));
      worstZ = worstOf(worstZ, std::abs(image.tristimulus.at(x, y, 1) - expected) / sigma);
      meanRatio += image.tristimulus.at(x, y, 1) / expected;
    }
  }
  meanRatio /= static_cast<double>(image.tristimulus.pixelCount());
  // No scattering, so no path is lost to it: the only noise is the wavelengths'.
  EXPECT_NEAR(meanRatio, 1.0, 2e-3);
  EXPECT_LT(worstZ, 5.0);
}

// Single scattering from a point light in a chromatic, forward-scattering slab, against the same
// integral evaluated numerically in the test: ∫∫ σs(λ)·p(θ)·I·S(λ)/r² · e^(−σt(λ)·(s + r)) ds ȳ dλ.
TEST(PathTracer, SingleScatteringInAChromaticMediumMatchesNumericalIntegration) {
  Scene scene;
  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, -1.0f};
  scene.camera.verticalFovDeg = 20.0f;
  Light lamp;
  lamp.type = LightType::Point;
  lamp.position = {0.8f, 0.0f, -1.2f};  // near the entrance: the far slab scatters it backwards
  lamp.spd = illuminant("D65");
  lamp.spd *= 1.0 / luminousIntegral(lamp.spd);
  lamp.intensity = 500.0f;
  scene.lights.push_back(lamp);
  HomogeneousMedium fog;
  fog.sigmaS = Spectrum::fromFunction([](double l) { return 0.3 * std::pow(550.0 / l, 4.0); });
  fog.sigmaA = Spectrum::fromFunction([](double l) { return 0.05 + 0.2 * (l - 360.0) / 470.0; });
  fog.g = 0.4f;
  fog.region = Bounds{{-50.0f, -50.0f, -5.0f}, {50.0f, 50.0f, -1.0f}};
  scene.medium = fog;
  ReferenceSettings settings;
  settings.width = settings.height = 5;
  settings.samplesPerPixel = 1024;
  settings.filter = PixelFilter::Centre;
  // Both estimators: direct's forced scattering, and global's free flights stopped after the
  // first event (one interaction: single scattering again).
  ReferenceImage forced = renderReference(scene, srgbTable(), settings);
  settings.transport = LightTransport::Global;
  settings.maxDepth = 1;
  ReferenceImage freeFlight = renderReference(scene, srgbTable(), settings);

  CameraTransform camera = cameraTransform(scene.camera, settings.width, settings.height);
  const Observer& cie = observer("cie1931");
  double worstZ[2] = {0.0, 0.0}, sumDifference[2] = {0.0, 0.0}, sumVariance[2] = {0.0, 0.0};
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      float u = (static_cast<float>(x) + 0.5f) / 5.0f, v = 1.0f - (static_cast<float>(y) + 0.5f) / 5.0f;
      glm::vec4 far = camera.inverseViewProjection * glm::vec4(u * 2.0f - 1.0f, v * 2.0f - 1.0f, 1.0f, 1.0f);
      glm::dvec3 d = glm::normalize(glm::dvec3(glm::vec3(far) / far.w));
      double tEnter = 1.0 / -d.z, tExit = 5.0 / -d.z;
      const int steps = 2000;
      double expectedY = 0.0;
      for (int i = kLambdaMinNm; i <= kLambdaMaxNm; ++i) {
        double l = i, sigmaS = fog.sigmaS.at(l), sigmaT = sigmaS + fog.sigmaA.at(l);
        double integral = 0.0;  // Simpson over the slab
        for (int k = 0; k <= steps; ++k) {
          double t = tEnter + (tExit - tEnter) * k / steps;
          glm::dvec3 p = d * t, toLight = glm::dvec3(lamp.position) - p;
          double r = glm::length(toLight);
          double cosTheta = glm::dot(toLight / r, d);
          double g = fog.g, q = 1.0 + g * g - 2.0 * g * cosTheta;
          double phase = (1.0 - g * g) / (4.0 * kPi * q * std::sqrt(q));
          double f = sigmaS * phase * lamp.intensity / (r * r) * std::exp(-sigmaT * (t - tEnter + r));
          integral += f * (k == 0 || k == steps ? 1.0 : (k % 2 ? 4.0 : 2.0));
        }
        integral *= (tExit - tEnter) / (3.0 * steps);
        double trapezoid = (i == kLambdaMinNm || i == kLambdaMaxNm) ? 0.5 : 1.0;
        expectedY += trapezoid * integral * lamp.spd.at(l) * cie.at(l).y();
      }
      expectedY *= absoluteTristimulusScale(cie);
      for (int e = 0; e < 2; ++e) {
        const ReferenceImage& image = e == 0 ? forced : freeFlight;
        double got = image.tristimulus.at(x, y, 1);
        double variance = image.variance.at(x, y, 1);
        worstZ[e] = worstOf(worstZ[e], std::abs(got - expectedY) / std::sqrt(variance));
        sumDifference[e] += got - expectedY;
        sumVariance[e] += variance;
      }
    }
  }
  // Per pixel, and all 25 together (a bias would show in the sum long before in one pixel).
  for (int e = 0; e < 2; ++e) {
    EXPECT_LT(worstZ[e], 5.0) << (e == 0 ? "forced scattering" : "free flights");
    EXPECT_LT(std::abs(sumDifference[e]) / std::sqrt(sumVariance[e]), 4.0) << (e == 0 ? "forced" : "free flights");
  }
}

// Jerlov 3C with the camera 1.5 m deep.
std::unique_ptr<underwater::WaterSection> coastalWater() {
  auto water = std::make_unique<underwater::WaterSection>();
  water->type.assign("3C");
  water->depthM = 1.5f;
  water->resolve();
  return water;
}

// A scene's water is traced as the same medium below its surface, isotropic.
TEST(PathTracer, WaterIsTheMediumBelowItsSurface) {
  Scene wet = litPlane(0.5, 1000.0f);
  wet.techniques.add(coastalWater());
  const auto& water = *wet.techniques.find<underwater::WaterSection>();
  Scene explicitMedium = litPlane(0.5, 1000.0f);
  HomogeneousMedium below;
  below.sigmaA = water.sigmaA;
  below.sigmaS = water.sigmaS;
  below.region = Bounds{{-1e7f, -1e7f, -1e7f}, {1e7f, 4.5f, 1e7f}};
  explicitMedium.medium = below;
  ReferenceSettings settings = small(4);
  ReferenceImage a = renderReference(wet, srgbTable(), settings);
  ReferenceImage b = renderReference(explicitMedium, srgbTable(), settings);
  EXPECT_EQ(a.tristimulus.pixels, b.tristimulus.pixels);
  // And the water does something: coastal water over 3 m dims the plane.
  ReferenceImage dry = renderReference(litPlane(0.5, 1000.0f), srgbTable(), settings);
  EXPECT_LT(a.tristimulus.at(24, 16, 1), 0.5f * dry.tristimulus.at(24, 16, 1));
}

// Direct transport scatters the environment once in the water, as it does the lights. Looking
// level from depth z into open water under L(ω) = L·max(0, ω·y) (SkyFromAbove): the light reaching
// depth z from above is ∫ L·μ·e^(−σt·z/μ) dω = 2πL·E₃(σt·z), and what the ray gathers of it,
// isotropically, ∫₀^∞ σs/(4π)·2πL·E₃(σt·z)·e^(−σt·s) ds = σs·L·E₃(σt·z)/(2σt) per wavelength.
TEST(PathTracer, TheWaterScattersTheEnvironmentIntoTheView) {
  Scene scene;
  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, -1.0f};
  scene.camera.verticalFovDeg = 30.0f;
  scene.techniques.add(coastalWater());
  scene.techniques.add(std::make_unique<SkyFromAbove>(600.0));
  const auto& water = *scene.techniques.find<underwater::WaterSection>();
  const double depthM = water.depthM;
  auto e3 = [](double tau) {  // E₃(τ) = ∫₀¹ μ·e^(−τ/μ) dμ, Simpson
    constexpr int kSteps = 2000;
    double sum = 0.0;
    for (int i = 1; i <= kSteps; ++i) {
      double mu = static_cast<double>(i) / kSteps;
      sum += (i == kSteps ? 1.0 : i % 2 ? 4.0 : 2.0) * mu * std::exp(-tau / mu);
    }
    return sum / (3.0 * kSteps);
  };
  Spectrum sky = illuminant("D65");
  sky *= 600.0 / luminousIntegral(sky);
  const Spectrum gathered = Spectrum::fromFunction([&](double lambdaNm) {
    const double s = water.sigmaS.at(lambdaNm), t = s + water.sigmaA.at(lambdaNm);
    return s * sky.at(lambdaNm) * e3(t * depthM) / (2.0 * t);
  });
  const Eigen::Vector3d xyz = observer("cie1931").integrate(gathered);
  const Eigen::Vector3d expected = xyz * (luminousIntegral(gathered) / xyz.y());  // absolute: 683 lm/W

  ReferenceSettings settings = small(131072);
  settings.width = settings.height = 1;  // the view ray level, through the pixel's centre
  settings.transport = LightTransport::Direct;
  const ReferenceImage image = renderReference(scene, srgbTable(), settings);
  for (int c = 0; c < 3; ++c) {
    const double got = image.tristimulus.pixels[static_cast<std::size_t>(c)];
    const double sigma = std::sqrt(image.variance.pixels[static_cast<std::size_t>(c)]);
    std::printf("channel %d: %.5g against %.5g (σ %.2g)\n", c, got, expected[c], sigma);
    EXPECT_GT(expected[c], 0.01);
    EXPECT_LT(std::abs(got - expected[c]), 5.0 * sigma) << "channel " << c;
    EXPECT_LT(sigma, 0.01 * expected[c]) << "channel " << c;
  }
}

TEST(PathTracer, BadSettingsAreErrorsNamingThem) {
  Scene scene = litPlane(0.5, 1000.0f);
  ReferenceSettings settings = small(4);
  settings.samplesPerPixel = 0;
  EXPECT_THROW(renderReference(scene, srgbTable(), settings), Error);
  settings = small(4);
  settings.wavelengths.count = 8;
  EXPECT_THROW(renderReference(scene, srgbTable(), settings), Error);
  settings = small(4);
  settings.observer = "nonesuch";
  EXPECT_THROW(renderReference(scene, srgbTable(), settings), Error);
  EXPECT_THROW(lightTransportFromName("photon"), Error);
  EXPECT_THROW(pixelFilterFromName("gauss"), Error);
}

}  // namespace
}  // namespace prism::reference

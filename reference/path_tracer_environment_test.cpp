// The path tracer aims at a technique's environment (environment_sampler.h) and weighs that
// against the BRDF's own directions: a floor under a sky with a small bright cap (a sun) held to
// its closed form, in both transports, and to the noise a BRDF sample alone would leave.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "reference/path_tracer.h"
#include "scene/procedural_mesh.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::reference {
namespace {

// D65 of luminance `sky` cd/m² from every direction above the horizon, and `sun` more within
// `radiusDeg` of a direction `zenithDeg` from the zenith.
class SkyWithSun final : public TechniqueSection {
 public:
  SkyWithSun(double sky, double sun, double radiusDeg, double zenithDeg)
      : mSky(sky), mSun(sun), mCosRadius(std::cos(radiusDeg * std::numbers::pi / 180.0)),
        mSunDirection(static_cast<float>(std::sin(zenithDeg * std::numbers::pi / 180.0)),
                      static_cast<float>(std::cos(zenithDeg * std::numbers::pi / 180.0)), 0.0f) {}
  std::string_view key() const override { return "sky_with_sun"; }
  std::string_view shaderDefine() const override { return "PRISM_TECHNIQUE_SKY_WITH_SUN"; }
  std::unique_ptr<TechniqueSection> clone() const override { return std::make_unique<SkyWithSun>(*this); }
  TechniqueBlock pack(const FramePackInput&) const override { return {}; }
  bool shadesObjects() const override { return true; }
  std::shared_ptr<const TechniqueEnvironment> environment(const RgbToSpectrumTable&) const override {
    struct Radiance final : TechniqueEnvironment {
      Spectrum spd;
      double sky, sun, cosRadius;
      glm::vec3 sunDirection;
      double radiance(const glm::vec3& d, double lambdaNm) const override {
        if (d.y <= 0.0f) return 0.0;
        const bool inSun = glm::dot(d, sunDirection) >= cosRadius;
        return (sky + (inSun ? sun : 0.0)) * spd.at(lambdaNm);
      }
    };
    auto e = std::make_shared<Radiance>();
    e->spd = illuminant("D65");
    e->spd *= 1.0 / luminousIntegral(e->spd);
    e->sky = mSky;
    e->sun = mSun;
    e->cosRadius = mCosRadius;
    e->sunDirection = mSunDirection;
    return e;
  }

 private:
  double mSky, mSun, mCosRadius;
  glm::vec3 mSunDirection;
};

// A Lambertian floor of albedo ρ (a technique's object: Lambertian) under that sky: irradiance
// π·L_sky from the sky and π·L_sun·sin²r·cos θ from the sun's cap (whole above the horizon), so
// Y = ρ·(L_sky + L_sun·sin²r·cos θ). A cosine-weighted direction meets the sun with a chance of
// sin²r·cos θ (9e-4 here), which carries 79 % of the light.
TEST(PathTracerEnvironment, AFloorUnderASmallSunIsItsClosedFormInBothTransports) {
  const double rho = 0.5, sky = 50.0, sun = 2e5, radiusDeg = 2.0, zenithDeg = 40.0;
  Scene scene;
  scene.camera.position = {0.0f, 3.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  Material floor;
  floor.reflectance = Spectrum::constant(rho);
  scene.materials.push_back(floor);
  scene.meshes.push_back(makePlane({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {20.0f, 20.0f}));
  scene.meshes[0].technique = "sky_with_sun";
  scene.techniques.add(std::make_unique<SkyWithSun>(sky, sun, radiusDeg, zenithDeg));
  const double sinR = std::sin(radiusDeg * std::numbers::pi / 180.0);
  const double expected = rho * (sky + sun * sinR * sinR * std::cos(zenithDeg * std::numbers::pi / 180.0));
  const Eigen::Vector3d d65 = observer("cie1931").integrate(illuminant("D65"));

  for (const LightTransport transport : {LightTransport::Direct, LightTransport::Global}) {
    ReferenceSettings settings;
    settings.width = settings.height = 1;  // the one pixel's centre is the camera's target
    settings.samplesPerPixel = 65536;  // one path's spread 1.4 × the mean: the mean's 0.5 %
    settings.filter = PixelFilter::Centre;
    settings.transport = transport;
    const ReferenceImage image = renderReference(scene, rendererRgbToSpectrumTable("srgb"), settings);
    const double y = image.tristimulus.pixels[1];
    const double sigma = std::sqrt(static_cast<double>(image.variance.pixels[1]));
    const double pathSpread = sigma * std::sqrt(static_cast<double>(settings.samplesPerPixel)) / y;
    std::printf("%s: Y %.3f (closed form %.3f), z %.2f, one path's spread %.3f of the mean\n",
                transport == LightTransport::Direct ? "direct" : "global", y, expected, (y - expected) / sigma,
                pathSpread);
    EXPECT_LT(std::abs(y - expected), 5.0 * sigma);
    EXPECT_NEAR(y / expected, 1.0, 0.02);  // 4 of the mean's standard errors
    // A BRDF sample alone: ≈ 0.79/√(9e-4) ≈ 26.
    EXPECT_LT(pathSpread, 2.0);
    EXPECT_NEAR(image.tristimulus.pixels[0] / y, d65.x() / d65.y(), 0.01);
    EXPECT_NEAR(image.tristimulus.pixels[2] / y, d65.z() / d65.y(), 0.01);
  }
}

}  // namespace
}  // namespace prism::reference

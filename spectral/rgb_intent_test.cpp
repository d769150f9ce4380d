#include "spectral/rgb_intent.h"

#include <gtest/gtest.h>

#include <cmath>

#include "spectral/observer.h"
#include "spectral/sigmoid_fit.h"
#include "spectral/table_test_support.h"

namespace prism {
namespace {

// Structure, and the albedo's colour, are checked against the small table; the unbounded and
// illuminant colours against exact fits (CIE76 residual below 1e-5 under the space's white).

// XYZ of a reflectance lit by the space's white (white Y = 1).
Eigen::Vector3d litXyz(const Spectrum& reflectance, const RgbColourSpace& space) {
  return reflectanceTristimulus(cie1931Observer(), reflectance, gamutWhiteIlluminant(space));
}

Eigen::Vector3d rgbXyz(const RgbColourSpace& space, const glm::vec3& rgb) {
  return space.rgbToXyz * Eigen::Vector3d(rgb.r, rgb.g, rgb.b);
}

TEST(RgbAlbedoSpectrum, IsTheTablesReflectanceOfTheClampedColour) {
  const RgbToSpectrumTable& t = smallSrgbTable();
  RgbAlbedoSpectrum albedo(t, glm::vec3(2.0f, 0.5f, -1.0f));
  EXPECT_EQ(albedo.coefficients(), t.lookup(glm::vec3(1.0f, 0.5f, 0.0f)));
  Spectrum r = albedo.toDense();
  for (int i = 0; i < kSpectrumSamples; ++i) {
    EXPECT_GE(r[i], 0.0);
    EXPECT_LE(r[i], 1.0);
  }
}

TEST(RgbAlbedoSpectrum, ReproducesTheColourUnderTheSpacesWhite) {
  // A 12³ table interpolates between fitted nodes: 1.6 % of the colour's XYZ at worst here.
  const RgbColourSpace& srgb = colourSpace("srgb");
  for (glm::vec3 rgb : {glm::vec3(0.8f, 0.2f, 0.1f), glm::vec3(0.1f, 0.5f, 0.3f), glm::vec3(0.5f)}) {
    Eigen::Vector3d got = litXyz(RgbAlbedoSpectrum(smallSrgbTable(), rgb).toDense(), srgb);
    Eigen::Vector3d want = rgbXyz(srgb, rgb);
    EXPECT_LT((got - want).norm(), 0.02 * want.norm()) << rgb.r << " " << rgb.g << " " << rgb.b;
  }
}

TEST(RgbUnboundedSpectrum, IsTwiceTheMaximumTimesTheReflectanceOfTheScaledColour) {
  const RgbToSpectrumTable& t = smallSrgbTable();
  RgbUnboundedSpectrum u(t, glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_FLOAT_EQ(u.scale(), 4.0f);
  EXPECT_EQ(u.coefficients(), t.lookup(glm::vec3(0.5f, 0.25f, 0.125f)));
  Spectrum reflectance = upsampledReflectanceSpectrum(u.coefficients());
  Spectrum dense = u.toDense();
  for (int i = 0; i < kSpectrumSamples; i += 10) {
    EXPECT_EQ(dense[i], 4.0 * reflectance[i]);
    EXPECT_EQ(u.at(static_cast<float>(kLambdaMinNm + i)), static_cast<float>(dense[i]));
  }
}

TEST(RgbUnboundedSpectrum, BlackAndUnusableChannelsGiveZeroNeverNaN) {
  const RgbToSpectrumTable& t = smallSrgbTable();
  EXPECT_EQ(RgbUnboundedSpectrum(t, glm::vec3(0.0f)).scale(), 0.0f);
  RgbUnboundedSpectrum bad(t, glm::vec3(NAN, INFINITY, -3.0f));
  EXPECT_EQ(bad.scale(), 0.0f);
  EXPECT_EQ(bad.at(550.0f), 0.0f);
  RgbUnboundedSpectrum huge(t, glm::vec3(3e38f, 1.0f, 0.0f));
  EXPECT_TRUE(std::isfinite(huge.scale()));
  EXPECT_TRUE(std::isfinite(huge.at(550.0f)));
  EXPECT_EQ(RgbUnboundedSpectrum::fitted(colourSpace("srgb"), glm::vec3(-1.0f, NAN, 0.0f)).scale(), 0.0f);
}

TEST(RgbUnboundedSpectrum, ReproducesAColourAboveOne) {
  // An exact fit: 2e-7 of the colour's XYZ measured.
  for (const char* name : {"srgb", "acescg"}) {
    const RgbColourSpace& space = colourSpace(name);
    glm::vec3 rgb(3.0f, 1.2f, 0.4f);
    Eigen::Vector3d got = litXyz(RgbUnboundedSpectrum::fitted(space, rgb).toDense(), space);
    Eigen::Vector3d want = rgbXyz(space, rgb);
    EXPECT_LT((got - want).norm(), 1e-5 * want.norm()) << name;
  }
}

TEST(RgbIlluminantSpectrum, HasTheColoursChromaticityAndLuminance) {
  // Reachable colours only: a wide gamut's pure primaries lie beyond every smooth reflectance.
  // Measured: chromaticity within 1.1e-7, luminance within 8e-6 (relative).
  for (const char* name : {"srgb", "rec2020", "acescg"}) {
    const RgbColourSpace& space = colourSpace(name);
    for (glm::vec3 rgb : {glm::vec3(1.0f, 0.6f, 0.2f), glm::vec3(0.2f, 0.3f, 4.5f), glm::vec3(0.3f, 1.0f, 0.2f)}) {
      Spectrum s = RgbIlluminantSpectrum::fitted(space, rgb, 250.0).toDense();
      Chromaticity got = xyzToXy(cie1931Observer().integrate(s));
      Eigen::Vector3d want = rgbXyz(space, rgb);
      Chromaticity wantXy = xyzToXy(want);
      EXPECT_NEAR(got.x, wantXy.x, 1e-6) << name;
      EXPECT_NEAR(got.y, wantXy.y, 1e-6) << name;
      EXPECT_NEAR(luminousIntegral(s), 250.0 * want.y(), 1e-4 * 250.0 * want.y()) << name;
    }
  }
}

TEST(RgbIlluminantSpectrum, WhiteIsTheSpacesWhiteIlluminant) {
  // (1, 1, 1) is about the flat reflectance ½ scaled by 2; not exactly, because a space's white
  // point (four decimals) and its illuminant's CIE 1931 chromaticity differ in the fourth decimal,
  // which the fit makes up with a slope of 4e-4 at most.
  for (const char* name : {"srgb", "acescg"}) {
    const RgbColourSpace& space = colourSpace(name);
    Spectrum s = RgbIlluminantSpectrum::fitted(space, glm::vec3(1.0f)).toDense();
    const Spectrum& white = gamutWhiteIlluminant(space);
    double norm = luminousIntegral(white);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(s[i], white[i] / norm, 1e-3 * white[i] / norm) << name;
  }
}

TEST(RgbIlluminantSpectrum, PointValuesAreTheDenseSpectrumInFloat) {
  const RgbColourSpace& srgb = colourSpace("srgb");
  RgbIlluminantSpectrum s(smallSrgbTable(), srgb, glm::vec3(0.9f, 0.5f, 0.1f), 3000.0);
  Spectrum dense = s.toDense();
  for (int i = 0; i < kSpectrumSamples; i += 7) {
    double lambda = kLambdaMinNm + i;
    EXPECT_NEAR(s.at(lambda), dense[i], 1e-6 * dense[i]) << lambda;
  }
}

}  // namespace
}  // namespace prism

#include "spectral/spectral_texture.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

// 2 × 2 texels over two functions at three wavelengths: b_0 flat 1, b_1 a ramp 0 → 1.
SpectralTexture twoByTwo() {
  SpectralTexture t;
  t.width = 2;
  t.height = 2;
  t.wavelengthsNm = {400.0, 500.0, 600.0};
  t.basis.resize(3, 2);
  t.basis << 1.0, 0.0, 1.0, 0.5, 1.0, 1.0;
  t.sampled = false;
  t.coefficients = {0.1f, 0.0f, 0.2f, 0.4f, 0.3f, 0.2f, 0.4f, 0.6f};  // (0,0) (1,0) (0,1) (1,1)
  checkSpectralTexture(t);
  return t;
}

TEST(SpectralTexture, BasisIsLinearBetweenItsWavelengthsAndConstantBeyond) {
  SpectralTexture t = twoByTwo();
  Eigen::MatrixXd b = basisAt(t, {300.0, 400.0, 450.0, 575.0, 900.0});
  EXPECT_DOUBLE_EQ(b(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(b(1, 1), 0.0);
  EXPECT_DOUBLE_EQ(b(2, 1), 0.25);
  EXPECT_DOUBLE_EQ(b(3, 1), 0.875);
  EXPECT_DOUBLE_EQ(b(4, 1), 1.0);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(b(i, 0), 1.0);
}

TEST(SpectralTexture, TexelCentresSampleTheirTexelAndMidpointsAverage) {
  SpectralTexture t = twoByTwo();
  // uv (0.25, 0.75): texel (0, 1)'s centre; row 0 is the top (v = 0).
  Eigen::VectorXd c = sampleTexels(t, {0.25f, 0.75f});
  EXPECT_NEAR(c[0], 0.3, 1e-7);
  EXPECT_NEAR(c[1], 0.2, 1e-7);
  // uv (0.5, 0.5): the four texels' mean.
  c = sampleTexels(t, {0.5f, 0.5f});
  EXPECT_NEAR(c[0], 0.25, 1e-7);
  EXPECT_NEAR(c[1], 0.3, 1e-7);
  // uv (0, 0.25): halfway between texel (1, 0), wrapped from the left, and texel (0, 0).
  c = sampleTexels(t, {0.0f, 0.25f});
  EXPECT_NEAR(c[0], 0.15, 1e-7);
  EXPECT_NEAR(c[1], 0.2, 1e-7);
  // The reflectance of texel (1, 1) at 550 nm: 0.4 + 0.6 · 0.75.
  EXPECT_NEAR(reflectanceAt(t, sampleTexels(t, {0.75f, 0.75f}), 550.0), 0.85, 1e-7);
}

}  // namespace
}  // namespace prism

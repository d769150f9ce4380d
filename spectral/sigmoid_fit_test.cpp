#include "spectral/sigmoid_fit.h"

#include <gtest/gtest.h>

#include "spectral/colour_difference.h"
#include "spectral/illuminant.h"

namespace prism {
namespace {

// The fitted spectrum's colour, recomputed independently of the fitter's own sums.
Eigen::Vector3d fittedLab(const SigmoidFit& fit, const RgbColourSpace& gamut) {
  Spectrum white = gamutWhiteIlluminant(gamut);
  const Observer& cie = observer("cie1931");
  Eigen::Vector3d xyz = reflectanceTristimulus(cie, upsampledReflectanceSpectrum(fit.coeffs), white);
  return xyzToLab(xyz, whiteTristimulus(cie, white));
}

TEST(SigmoidFit, ReproducesInGamutSrgbAlbedos) {
  const RgbColourSpace& srgb = colourSpace("srgb");
  SigmoidFitter fitter(srgb, gamutWhiteIlluminant(srgb), observer("cie1931"));
  Eigen::Vector3d white = whiteTristimulus(observer("cie1931"), gamutWhiteIlluminant(srgb));
  for (Eigen::Vector3d rgb : {Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(0.8, 0.2, 0.1),
                              Eigen::Vector3d(0.1, 0.6, 0.2), Eigen::Vector3d(0.05, 0.1, 0.7),
                              Eigen::Vector3d(0.9, 0.85, 0.1), Eigen::Vector3d(0.02, 0.02, 0.02)}) {
    SigmoidFit fit = fitter.fit(rgb);
    EXPECT_LT(fit.deltaE76, 1e-3) << rgb.transpose();
    Eigen::Vector3d target = xyzToLab(srgb.rgbToXyz * rgb, white);
    EXPECT_LT(deltaE(fittedLab(fit, srgb), target, DeltaEFormula::Ciede2000), 5e-3) << rgb.transpose();
  }
}

TEST(SigmoidFit, GreyIsFlat) {
  const RgbColourSpace& srgb = colourSpace("srgb");
  SigmoidFitter fitter(srgb, gamutWhiteIlluminant(srgb), observer("cie1931"));
  Spectrum s = upsampledReflectanceSpectrum(fitter.fit(Eigen::Vector3d::Constant(0.3)).coeffs);
  for (int l = 400; l <= 700; l += 50) EXPECT_NEAR(s.at(l), 0.3, 2e-3) << l;
}

TEST(SigmoidFit, AlbedoIsClampedToZeroOne) {
  const RgbColourSpace& srgb = colourSpace("srgb");
  SigmoidFitter fitter(srgb, gamutWhiteIlluminant(srgb), observer("cie1931"));
  SigmoidFit over = fitter.fit(Eigen::Vector3d(1.7, 0.5, -0.3));
  SigmoidFit clamped = fitter.fit(Eigen::Vector3d(1.0, 0.5, 0.0));
  EXPECT_EQ(over.coeffs, clamped.coeffs);
}

}  // namespace
}  // namespace prism

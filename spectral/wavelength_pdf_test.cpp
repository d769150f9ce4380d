#include "spectral/wavelength_pdf.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "spectral/illuminant.h"

namespace prism {
namespace {

// ∫ p over [min, max], bin by bin (density is constant on each 1 nm bin from min).
double integral(const WavelengthPdf& pdf) {
  double sum = 0.0;
  for (double a = pdf.minNm(); a < pdf.maxNm(); a += 1.0) {
    double b = std::min(a + 1.0, pdf.maxNm());
    sum += pdf.density(0.5 * (a + b)) * (b - a);
  }
  return sum;
}

TEST(WavelengthPdf, IntegratesToOne) {
  const Observer& cie = observer("cie1931");
  // A range whose ends are not on the 1 nm grid: the last bin is shorter.
  for (auto [minNm, maxNm] : {std::pair{360.0, 830.0}, std::pair{380.5, 779.25}}) {
    EXPECT_NEAR(integral(WavelengthPdf::observerResponse(cie, minNm, maxNm)), 1.0, 1e-12);
    EXPECT_NEAR(integral(WavelengthPdf::lightsAndObserver(illuminant("F11"), cie, minNm, maxNm)), 1.0, 1e-12);
    EXPECT_NEAR(integral(WavelengthPdf::lightsAndObserver(illuminant("led:450:20"), cie, minNm, maxNm)), 1.0, 1e-12);
  }
}

TEST(WavelengthPdf, InvertingTheCdfSpansTheRangeAndReportsTheDensityThere) {
  WavelengthPdf pdf = WavelengthPdf::lightsAndObserver(illuminant("F11"), observer("cie1931"), 380.0, 780.0);
  EXPECT_DOUBLE_EQ(pdf.invert(0.0).lambdaNm, 380.0);
  EXPECT_NEAR(pdf.invert(1.0).lambdaNm, 780.0, 1e-9);  // the CDF's sum rounds
  double previous = 380.0;
  for (int k = 1; k < 1000; ++k) {
    WavelengthPdf::Sample s = pdf.invert(k / 1000.0);
    EXPECT_GE(s.lambdaNm, previous);
    EXPECT_DOUBLE_EQ(s.pdf, pdf.density(s.lambdaNm)) << s.lambdaNm;
    previous = s.lambdaNm;
  }
}

TEST(WavelengthPdf, LightsKeepTheDefensiveShareWhereverTheObserverResponds) {
  // A 20 nm LED at 450 nm emits next to nothing beyond 520 nm; the pdf must still reach every
  // wavelength the observer sees (else a surface lit there by the background or a mis-weighed
  // lamp would be lost: bias), with at least α of Importance's density.
  const Observer& cie = observer("cie1931");
  WavelengthPdf observerPdf = WavelengthPdf::observerResponse(cie, 360.0, 830.0);
  WavelengthPdf lights = WavelengthPdf::lightsAndObserver(illuminant("led:450:20"), cie, 360.0, 830.0);
  for (double lambda = 360.5; lambda < 830.0; lambda += 1.0) {
    if (cie.at(lambda).sum() <= 0.0) continue;
    EXPECT_GT(lights.density(lambda), 0.0) << lambda;
    EXPECT_GE(lights.density(lambda), kLightsDefensiveFraction * observerPdf.density(lambda) * (1.0 - 1e-12))
        << lambda;
  }
  // No lights the observer sees: Importance's pdf itself.
  WavelengthPdf dark = WavelengthPdf::lightsAndObserver(Spectrum(), cie, 360.0, 830.0);
  for (double lambda = 360.5; lambda < 830.0; lambda += 1.0)
    EXPECT_DOUBLE_EQ(dark.density(lambda), observerPdf.density(lambda)) << lambda;
}

TEST(WavelengthPdf, LightsFollowTheEmissionTimesEachCurveInEqualShares) {
  // Where the defensive share is negligible, p ∝ Σ_c E·c̄_c / ∫E·c̄_c: the ratio of two
  // wavelengths' densities is that of this sum (on bins of 1 nm from an integer, Simpson's rule
  // is exact for the piecewise-linear products, which is what each bin holds).
  const Observer& cie = observer("cie1931");
  Spectrum led = illuminant("led:450:20");
  WavelengthPdf pdf = WavelengthPdf::lightsAndObserver(led, cie, 360.0, 830.0);
  WavelengthPdf observerPdf = WavelengthPdf::observerResponse(cie, 360.0, 830.0);
  auto lightPart = [&](double lambda) {
    return pdf.density(lambda) - kLightsDefensiveFraction * observerPdf.density(lambda);
  };
  auto binMass = [&](double a) -> Eigen::Vector3d {  // ∫ E·c̄ over [a, a + 1], both linear there
    auto f = [&](double l) -> Eigen::Vector3d { return led.at(l) * cie.at(l); };
    Eigen::Vector3d sum = f(a) + 4.0 * f(a + 0.5) + f(a + 1.0);
    return sum / 6.0;
  };
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (double a = 360.0; a < 830.0; a += 1.0) total += binMass(a);
  auto balanced = [&](double a) { return binMass(a).cwiseQuotient(total).sum(); };
  EXPECT_NEAR(lightPart(440.5) / lightPart(450.5), balanced(440.0) / balanced(450.0), 1e-12);
  EXPECT_NEAR(lightPart(462.5) / lightPart(450.5), balanced(462.0) / balanced(450.0), 1e-12);
}

TEST(WavelengthPdf, AnObserverBlindToTheRangeIsAnError) {
  // A camera's curves are zero outside their measured band: nothing there to importance-sample.
  EXPECT_THROW(WavelengthPdf::observerResponse(observer("nikon_d850"), 800.0, 830.0), Error);
}

}  // namespace
}  // namespace prism

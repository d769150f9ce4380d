#include "spectral/colour_space.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace prism {
namespace {

Eigen::Matrix3d matrix(std::initializer_list<double> v) {
  Eigen::Matrix3d m;
  auto it = v.begin();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = *it++;
  return m;
}

void expectNear(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, double tolerance) {
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), tolerance) << "derived\n" << a << "\npublished\n" << b;
}

// A caller's primaries are checked: degenerate ones gave a NaN matrix, silently.
TEST(ColourSpace, DegeneratePrimariesAreRefused) {
  const Chromaticity d65{0.3127, 0.3290};
  EXPECT_NO_THROW(RgbColourSpace::fromPrimaries("ok", {0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, d65, Transfer::Linear));
  EXPECT_THROW(RgbColourSpace::fromPrimaries("line", {0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}, d65, Transfer::Linear), Error);
  EXPECT_THROW(RgbColourSpace::fromPrimaries("flat", {0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.31, 0.0},
                                             Transfer::Linear),
               Error);
  EXPECT_THROW(RgbColourSpace::fromPrimaries("nan", {0.64, std::nan("")}, {0.30, 0.60}, {0.15, 0.06}, d65,
                                             Transfer::Linear),
               Error);
}

TEST(ColourSpace, SrgbMatchesIec61966) {
  // IEC 61966-2-1:1999 Eq. 7 (linear RGB → XYZ), published to 4 decimals.
  expectNear(colourSpace("srgb").rgbToXyz,
             matrix({0.4124, 0.3576, 0.1805, 0.2126, 0.7152, 0.0722, 0.0193, 0.1192, 0.9505}), 1e-4);
}

TEST(ColourSpace, DisplayP3MatchesSmpteEg432) {
  // SMPTE EG 432-1:2010 (P3 primaries with a D65 white), 4 decimals.
  expectNear(colourSpace("display-p3").rgbToXyz,
             matrix({0.4866, 0.2657, 0.1982, 0.2290, 0.6917, 0.0793, 0.0000, 0.0451, 1.0439}), 1e-4);
}

TEST(ColourSpace, Rec2020MatchesBt2087) {
  // ITU-R BT.2087-0 Annex (BT.2020 RGB → XYZ), 4 decimals.
  expectNear(colourSpace("rec2020").rgbToXyz,
             matrix({0.6370, 0.1446, 0.1689, 0.2627, 0.6780, 0.0593, 0.0000, 0.0281, 1.0610}), 1e-4);
}

TEST(ColourSpace, AcesMatchesAcademyPublishedMatrices) {
  // SMPTE ST 2065-1:2012 §4.1.4 (AP0) and Academy S-2014-004 §4.1.2 (AP1), 10 decimals.
  expectNear(colourSpace("aces2065-1").rgbToXyz,
             matrix({0.9525523959, 0.0, 0.0000936786, 0.3439664498, 0.7281660966, -0.0721325464,
                     0.0, 0.0, 1.0088251844}),
             1e-8);
  expectNear(colourSpace("acescg").rgbToXyz,
             matrix({0.6624541811, 0.1340042065, 0.1561876870, 0.2722287168, 0.6740817658,
                     0.0536895174, -0.0055746495, 0.0040607335, 1.0103391003}),
             1e-8);
}

TEST(ColourSpace, WhiteMapsToWhiteAndInverseIsExact) {
  for (const std::string& name : listColourSpaces()) {
    const RgbColourSpace& s = colourSpace(name);
    EXPECT_TRUE((s.rgbToXyz * Eigen::Vector3d::Ones()).isApprox(s.whiteXyz(), 1e-12)) << name;
    EXPECT_TRUE((s.xyzToRgb * s.rgbToXyz).isApprox(Eigen::Matrix3d::Identity(), 1e-12)) << name;
  }
}

TEST(ColourSpace, TransferFunctionsRoundTrip) {
  for (const std::string& name : listColourSpaces()) {
    const RgbColourSpace& s = colourSpace(name);
    for (double v : {0.0, 0.001, 0.01, 0.2, 0.5, 1.0}) {
      Eigen::Vector3d x(v, v, v);
      EXPECT_TRUE(s.decode(s.encode(x)).isApprox(x, 1e-5) || v == 0.0) << name << " " << v;
    }
  }
  // IEC 61966-2-1: linear 0.5 encodes to 0.7354 (to 4 decimals); 18 % grey to 0.4614.
  EXPECT_NEAR(colourSpace("srgb").encode(Eigen::Vector3d::Constant(0.5)).x(), 0.735357, 1e-5);
  EXPECT_NEAR(colourSpace("srgb").encode(Eigen::Vector3d::Constant(0.18)).x(), 0.461356, 1e-5);
  EXPECT_EQ(colourSpace("srgb").encode(Eigen::Vector3d::Constant(-0.2)).x(), 0.0);
}

TEST(ChromaticAdaptation, BradfordD65ToD50MatchesLindbloom) {
  // Lindbloom's published Bradford matrix, from his white points (ASTM E308 XYZ).
  Eigen::Vector3d d65(0.95047, 1.0, 1.08883), d50(0.96422, 1.0, 0.82521);
  expectNear(chromaticAdaptation(Adaptation::Bradford, d65, d50),
             matrix({1.0478112, 0.0228866, -0.0501270, 0.0295424, 0.9904844, -0.0170491,
                     -0.0092345, 0.0150436, 0.7521316}),
             1e-4);
}

TEST(ChromaticAdaptation, VonKriesD65ToD50MatchesLindbloom) {
  Eigen::Vector3d d65(0.95047, 1.0, 1.08883), d50(0.96422, 1.0, 0.82521);
  expectNear(chromaticAdaptation(Adaptation::VonKries, d65, d50),
             matrix({1.0160803, 0.0552297, -0.0521326, 0.0060666, 0.9955661, -0.0012235, 0.0, 0.0,
                     0.7578869}),
             1e-4);
}

TEST(ChromaticAdaptation, EveryMethodMapsSourceWhiteToTargetWhite) {
  Eigen::Vector3d a = xyToXyz({0.44757, 0.40745}), d65 = xyToXyz({0.3127, 0.3290});
  for (Adaptation m : {Adaptation::Bradford, Adaptation::Cat02, Adaptation::VonKries})
    EXPECT_TRUE((chromaticAdaptation(m, a, d65) * a).isApprox(d65, 1e-12));
}

TEST(ColourSpace, ConversionBetweenSpacesAdaptsTheWhite) {
  Eigen::Matrix3d m = rgbToRgb(colourSpace("srgb"), colourSpace("acescg"));
  EXPECT_TRUE((m * Eigen::Vector3d::Ones()).isApprox(Eigen::Vector3d::Ones(), 1e-9));
  Eigen::Matrix3d same = rgbToRgb(colourSpace("srgb"), colourSpace("rec2020"));
  // BT.2087-0 Table 2: BT.709 → BT.2020 first row 0.6274 0.3293 0.0433.
  EXPECT_NEAR(same(0, 0), 0.6274, 1e-4);
  EXPECT_NEAR(same(0, 1), 0.3293, 1e-4);
  EXPECT_NEAR(same(0, 2), 0.0433, 1e-4);
}

TEST(ColourSpace, P3IsDisplayP3) { EXPECT_EQ(&colourSpace("p3"), &colourSpace("display-p3")); }

TEST(ColourSpace, UnknownNamesAreErrors) {
  EXPECT_THROW(colourSpace("adobe-rgb"), Error);
  EXPECT_THROW(adaptationFromName("cat16"), Error);
}

}  // namespace
}  // namespace prism

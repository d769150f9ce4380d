#include "spectral/spectrum.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/error.h"

namespace prism {
namespace {

// A table a library's caller builds is checked as a file's is: an Error, not an abort, and no NaN.
TEST(TabulatedSpectrumTest, RefusesABadTableWithAnError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(TabulatedSpectrum({400, 500}, {1.0}, Extrapolation::Zero), Error);
  EXPECT_THROW(TabulatedSpectrum({400}, {1.0}, Extrapolation::Zero), Error);
  EXPECT_THROW(TabulatedSpectrum({500, 400}, {1.0, 1.0}, Extrapolation::Zero), Error);
  EXPECT_THROW(TabulatedSpectrum({400, 400}, {1.0, 1.0}, Extrapolation::Zero), Error);
  EXPECT_THROW(TabulatedSpectrum({400, nan}, {1.0, 1.0}, Extrapolation::Zero), Error);
  EXPECT_THROW(TabulatedSpectrum({400, 500}, {1.0, nan}, Extrapolation::Zero), Error);
  EXPECT_NO_THROW(TabulatedSpectrum({400, 500}, {1.0, 2.0}, Extrapolation::Zero));
}

TEST(Spectrum, ConstantIntegratesToTheDomainWidth) {
  EXPECT_DOUBLE_EQ(Spectrum::constant(2.0).integral(), 2.0 * (kLambdaMaxNm - kLambdaMinNm));
}

TEST(Spectrum, TrapezoidIsExactForLinearFunctions) {
  Spectrum s = Spectrum::fromFunction([](double l) { return 3.0 * l - 1000.0; });
  double exact = 1.5 * (830.0 * 830.0 - 360.0 * 360.0) - 1000.0 * 470.0;
  EXPECT_NEAR(s.integral(), exact, 1e-6 * std::abs(exact));
}

TEST(Spectrum, AtInterpolatesLinearlyAndIsZeroOutside) {
  Spectrum s = Spectrum::fromFunction([](double l) { return l; });
  EXPECT_DOUBLE_EQ(s.at(500.25), 500.25);
  EXPECT_DOUBLE_EQ(s.at(830.0), 830.0);
  EXPECT_EQ(s.at(359.9), 0.0);
  EXPECT_EQ(s.at(830.1), 0.0);
  EXPECT_EQ(s.at(std::nan("")), 0.0);
}

TEST(TabulatedSpectrum, ResamplesLinearlyAtEachNode) {
  TabulatedSpectrum t({400.0, 410.0}, {1.0, 2.0}, Extrapolation::Zero);
  Spectrum d = t.toDense();
  EXPECT_DOUBLE_EQ(d[400 - kLambdaMinNm], 1.0);
  EXPECT_DOUBLE_EQ(d[403 - kLambdaMinNm], 1.3);
  EXPECT_DOUBLE_EQ(d[410 - kLambdaMinNm], 2.0);
}

TEST(TabulatedSpectrum, ALineBetweenWholeNanometresKeepsItsEnergy) {
  // A spectrometer's mercury line, 0.2 nm wide at 546.1 nm on a flat floor of 1: its triangle
  // holds 0.2 · 1000 / 2 = 100 nm·units. Sampling at whole nanometres alone saw none of it.
  TabulatedSpectrum line({360.0, 546.0, 546.1, 546.2, 830.0}, {1.0, 1.0, 1001.0, 1.0, 1.0},
                         Extrapolation::Zero);
  Spectrum d = line.toDense();
  EXPECT_NEAR(d.integral(), 470.0 + 100.0, 1e-9);
  // Its centroid stays at 546.1 nm: the energy goes to 546 and 547 nm in the ratio 9 : 1.
  EXPECT_NEAR((d[546 - kLambdaMinNm] - 1.0) / (d[547 - kLambdaMinNm] - 1.0), 9.0, 1e-9);
  EXPECT_DOUBLE_EQ(d[545 - kLambdaMinNm], 1.0);
  EXPECT_DOUBLE_EQ(d[548 - kLambdaMinNm], 1.0);
}

TEST(TabulatedSpectrum, SamplesOnWholeNanometresAreTakenAsTheyAre) {
  // 1 nm and 5 nm tables (the CIE's) have no detail between nodes: each node is the table's value.
  std::vector<double> lambdas, values;
  for (int l = 380; l <= 780; l += 5) {
    lambdas.push_back(l);
    values.push_back(std::sin(0.05 * l) + 1.5);
  }
  TabulatedSpectrum t(lambdas, values, Extrapolation::Zero);
  Spectrum d = t.toDense();
  for (int l = 360; l <= 830; ++l) EXPECT_EQ(d[l - kLambdaMinNm], t.at(l)) << l;
}

TEST(TabulatedSpectrum, AFineTableIntegratesToItsOwnIntegral) {
  // 0.37 nm steps from 401.3 nm, a 1 nm box of 50 at 540 nm on a smooth floor: the dense integral
  // is the table's own trapezoid sum.
  std::vector<double> lambdas, values;
  double exact = 0.0;
  for (int k = 0; k < 807; ++k) {
    double l = 401.3 + 0.37 * k;
    double v = l > 540.0 && l < 541.0 ? 50.0 : 0.5 + 0.5 * std::cos(0.3 * l);
    if (k > 0) exact += 0.5 * (v + values.back()) * (l - lambdas.back());
    lambdas.push_back(l);
    values.push_back(v);
  }
  TabulatedSpectrum t(lambdas, values, Extrapolation::Zero);
  EXPECT_NEAR(t.toDense().integral(), exact, 1e-12 * exact);
}

// Dense integral and centroid (λ weighted by the trapezoid rule's weights).
std::pair<double, double> integralAndCentroid(const Spectrum& d) {
  double sum = 0.0, moment = 0.0;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const double w = (i == 0 || i == kSpectrumSamples - 1) ? 0.5 : 1.0;
    sum += w * d[i];
    moment += w * d[i] * (kLambdaMinNm + i);
  }
  return {sum, moment / sum};
}

TEST(TabulatedSpectrum, SamplesOfBothKindsKeepTheIntegralAndCentroid) {
  // Whole-nanometre feet, an apex between them: the triangle's area and centroid, exactly. (Point
  // values at some nodes beside averages at others lost 15 % of the first.)
  for (auto [left, apex, right] : {std::array{545.0, 546.5, 548.0}, std::array{546.0, 546.5, 548.0}}) {
    TabulatedSpectrum t({360.0, left, apex, right, 830.0}, {0.0, 0.0, 1000.0, 0.0, 0.0}, Extrapolation::Zero);
    auto [area, centroid] = integralAndCentroid(t.toDense());
    EXPECT_NEAR(area, 500.0 * (right - left), 1e-9) << apex;
    EXPECT_NEAR(centroid, (left + apex + right) / 3.0, 1e-9) << apex;
  }
}

TEST(TabulatedSpectrum, AveragesStayWithinTheTablesValues) {
  // A reflectance of 1 sampled every 0.37 nm is 1 at every node, not 1 + 1e-14 (which a metamer
  // search refuses as above 1).
  std::vector<double> lambdas, values;
  for (int k = 0; k < 1300; ++k) {
    lambdas.push_back(359.5 + 0.37 * k);
    values.push_back(1.0);
  }
  Spectrum d = TabulatedSpectrum(lambdas, values, Extrapolation::Clamp).toDense();
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_EQ(d[i], 1.0) << kLambdaMinNm + i;
}

TEST(TabulatedSpectrum, ExtrapolationRuleIsExplicit) {
  TabulatedSpectrum zero({400.0, 700.0}, {0.2, 0.8}, Extrapolation::Zero);
  TabulatedSpectrum clamp({400.0, 700.0}, {0.2, 0.8}, Extrapolation::Clamp);
  EXPECT_EQ(zero.at(390.0), 0.0);
  EXPECT_EQ(zero.at(710.0), 0.0);
  EXPECT_EQ(clamp.at(390.0), 0.2);
  EXPECT_EQ(clamp.at(710.0), 0.8);
}

TEST(Blackbody, PeakFollowsWiensDisplacementLaw) {
  // Wien's constant b = 2.897771955e-3 m·K (CODATA 2018): λ_max = b / T.
  for (double t : {5000.0, 6500.0}) {
    Spectrum s = blackbody(t);
    int peak = 0;
    for (int i = 1; i < kSpectrumSamples; ++i)
      if (s[i] > s[peak]) peak = i;
    EXPECT_NEAR(kLambdaMinNm + peak, 2.897771955e6 / t, 0.5) << t << " K";
  }
}

TEST(Blackbody, MatchesPlanckAtAKnownPoint) {
  // 5000 K at 500 nm: c1L/λ⁵/(exp(c2/(λT)) − 1) with the CODATA radiation constants
  // c1L = 2hc² = 1.191042972e-16 W·m²·sr⁻¹ and c2 = 1.438776877e-2 m·K.
  double lambda = 500e-9;
  double expected = 1.191042972e-16 / std::pow(lambda, 5) / std::expm1(1.438776877e-2 / (lambda * 5000.0)) * 1e-9;
  EXPECT_NEAR(planckRadianceWPerSrM2Nm(500.0, 5000.0), expected, 1e-8 * expected);
}

TEST(Blackbody, RejectsNonPositiveTemperature) {
  EXPECT_THROW(blackbody(0.0), Error);
  EXPECT_THROW(blackbody(-5.0), Error);
}

TEST(BoxReflectance, BlueGreenRedBandsWithTheThesisThresholds) {
  Spectrum s = boxReflectanceSpectrum(glm::vec3(0.8f, 0.5f, 0.2f));
  EXPECT_FLOAT_EQ(static_cast<float>(s.at(494.0)), 0.2f);
  EXPECT_FLOAT_EQ(static_cast<float>(s.at(495.0)), 0.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(s.at(569.0)), 0.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(s.at(570.0)), 0.8f);
  Spectrum clamped = boxReflectanceSpectrum(glm::vec3(2.0f, NAN, -1.0f));
  EXPECT_EQ(clamped.at(700.0), 1.0);
  EXPECT_EQ(clamped.at(520.0), 0.0);
  EXPECT_EQ(clamped.at(400.0), 0.0);
}

TEST(SigmoidSpectrum, HugeArgumentsReachTheLimitsNotAHalf) {
  // x·x overflows past ~1.8e19; S must still be ≈ 1 or ≈ 0 there, not ½.
  EXPECT_EQ(sigmoidSpectrum(glm::vec3(0, 0, 3e19f)).at(500.0), 1.0);
  EXPECT_EQ(sigmoidSpectrum(glm::vec3(0, 0, -3e19f)).at(500.0), 0.0);
  EXPECT_NEAR(sigmoidSpectrum(glm::vec3(0, 0, 5e8f)).at(500.0), 1.0, 1e-7);
}

TEST(SigmoidSpectrum, ZeroCoefficientsGiveHalfEverywhere) {
  Spectrum s = sigmoidSpectrum(glm::vec3(0.0f));
  EXPECT_FLOAT_EQ(static_cast<float>(s.maxValue()), 0.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(s.at(361.0)), 0.5f);
}

TEST(SigmoidSpectrum, StaysWithinZeroOneAndFiniteForExtremeCoefficients) {
  for (glm::vec3 c : {glm::vec3(1e30f, 0, 0), glm::vec3(-1e30f, 0, 0), glm::vec3(0, 0, INFINITY),
                      glm::vec3(0.01f, -9.0f, 2000.0f), glm::vec3(0, 0, 3e19f), glm::vec3(0, 0, -3e19f)}) {
    Spectrum s = sigmoidSpectrum(c);
    for (double v : s.values()) {
      EXPECT_TRUE(std::isfinite(v));
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
  }
}

}  // namespace
}  // namespace prism

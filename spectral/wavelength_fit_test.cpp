#include "spectral/wavelength_fit.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "core/cache_dir_test_support.h"
#include "core/error.h"
#include "core/fnv1a.h"
#include "spectral/colour_checker.h"
#include "spectral/illuminant.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/sampling.h"

namespace prism {
namespace {

TEST(WavelengthFit, FittedWavelengthsAreAscendingWholeNanometresInRange) {
  const Observer& cie = observer("cie1931");
  WavelengthFitProblem problem{{illuminant("F2")}, colourCheckerReflectances(), 8, 380, 730};
  const FittedWavelengths set = fitWavelengths(problem, cie);
  ASSERT_EQ(set.lambdaNm.size(), 8u);
  ASSERT_EQ(set.weights.cols(), 8);
  for (std::size_t i = 0; i < set.lambdaNm.size(); ++i) {
    EXPECT_EQ(set.lambdaNm[i], std::round(set.lambdaNm[i]));
    EXPECT_GE(set.lambdaNm[i], 380.0);
    EXPECT_LE(set.lambdaNm[i], 730.0);
    if (i > 0) {
      EXPECT_GT(set.lambdaNm[i], set.lambdaNm[i - 1]);
    }
  }
  // More wavelengths never fit worse than fewer on the same problem.
  const FittedWavelengths four = fitWavelengths({{illuminant("F2")}, colourCheckerReflectances(), 4, 380, 730}, cie);
  EXPECT_LE(fitError(set, problem, cie).mean, fitError(four, problem, cie).mean);
}

// The light within a range integrates to the range's own integral, its ends included by the part
// of their intervals inside it; the whole band leaves the light as it is.
TEST(WavelengthFit, TheLightWithinARangeIntegratesOverTheRangeAlone) {
  const Spectrum one = Spectrum::constant(1.0);
  EXPECT_NEAR(lightWithinRange(one, 500.0, 600.0).integral(), 100.0, 1e-12);  // 101.0 with its ends' ramps
  EXPECT_NEAR(lightWithinRange(one, 500.25, 599.5).integral(), 99.25, 1e-12);
  const Spectrum d65 = illuminant("D65");
  const Spectrum whole = lightWithinRange(d65, kLambdaMinNm, kLambdaMaxNm);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_EQ(whole[i], d65[i]) << i;
  // A linear light's integral over the range is exact: ∫ x dx over [500, 600] = 55 000.
  Spectrum ramp;
  for (int i = 0; i < kSpectrumSamples; ++i) ramp[i] = kLambdaMinNm + i;
  EXPECT_NEAR(lightWithinRange(ramp, 500.0, 600.0).integral(), 55000.0, 1e-9);
}

// A range narrower than four points of n = 4's 20 nm seed grid (80 nm) fits from the other seeds:
// the grid's combinations once ran past its end, without end.
TEST(WavelengthFit, ANarrowRangeFitsFourWavelengths) {
  const FittedWavelengths set =
      fitWavelengths({{illuminant("D65")}, colourCheckerReflectances(), 4, 360, 400}, observer("cie1931"));
  ASSERT_EQ(set.lambdaNm.size(), 4u);
  EXPECT_GE(set.lambdaNm.front(), 360.0);
  EXPECT_LE(set.lambdaNm.back(), 400.0);
}

// A light that z̄ barely sees (a far-red LED: its white's Z is 1e-81 of its Y) fits against the
// floored white: weights of 1/Z overflowed its least squares, every candidate's error was NaN, and
// the fit returned no wavelengths at all (cached, then aborting the renderer).
TEST(WavelengthFit, AFarRedLightFits) {
  const Observer& cie = observer("cie1931");
  const WavelengthFitProblem problem{{illuminant("led:780:10")}, colourCheckerReflectances(), 16};
  const Eigen::Vector3d white = cie.integrate(illuminant("led:780:10"));
  EXPECT_LT(white.z(), 1e-60 * white.y());
  const FittedWavelengths set = fitWavelengths(problem, cie);
  ASSERT_EQ(set.lambdaNm.size(), 16u);
  const FitError error = fitError(set, problem, cie);
  EXPECT_TRUE(std::isfinite(error.mean));
  EXPECT_LT(error.mean, 1.0);
}

// A sodium lamp's line at 590 nm has no CIE 1964 Z at all. Its white's Z, floored at 1e-6 of Y,
// weighed its pairs' Z errors by 10¹² against daylight's, and the least squares' ridge, scaled by
// them, crushed the Z row: daylight beside the lamp came out yellow, 30.7 mean ΔE00 on the chart
// (a new user's street scene: 15.9 from the reference mode). fitWhite floors each channel at 1 %.
TEST(WavelengthFit, ALightWithoutAChannelLeavesItToTheOtherLights) {
  const Observer& cie1964 = observer("cie1964");
  EXPECT_EQ(cie1964.integrate(illuminant("nist:LPS")).z(), 0.0);
  const std::vector<Spectrum> chart = colourCheckerReflectances();
  const WavelengthFitProblem both{{illuminant("D65"), illuminant("nist:LPS")}, chart, 16};
  const FittedWavelengths set = fitWavelengths(both, cie1964);
  for (const char* light : {"D65", "nist:LPS"}) {
    const FitError alone = fitError(set, WavelengthFitProblem{{illuminant(light)}, chart, 16}, cie1964);
    std::printf("%s beside the other, 16 wavelengths, CIE 1964: chart mean ΔE00 %.3f, max %.3f\n", light, alone.mean,
                alone.max);
    EXPECT_LT(alone.mean, 0.2) << light;
  }
}

// A light at the range's end, 1 nm wide: 16 whole-nm wavelengths must reach where it is e^−225 of
// its peak. Those nodes weigh 0; the least squares gave them ±1e92, ∞ in the renderer's floats,
// which made every pixel NaN.
TEST(WavelengthFit, NodesWithoutLightWeighNothing) {
  const Observer& cie = observer("cie1931");
  const Spectrum led = illuminant("led:830:1");
  const WavelengthFitProblem problem{{led}, colourCheckerReflectances(), 16};
  const FittedWavelengths set = fitWavelengths(problem, cie);
  const double peak = led[830 - kLambdaMinNm];
  for (std::size_t i = 0; i < set.lambdaNm.size(); ++i) {
    const bool dark = led[static_cast<int>(set.lambdaNm[i]) - kLambdaMinNm] < 1e-12 * peak;
    for (int c = 0; c < 3; ++c) {
      if (dark) {
        EXPECT_EQ(set.weights(c, static_cast<Eigen::Index>(i)), 0.0) << set.lambdaNm[i];
      }
      EXPECT_LT(std::abs(set.weights(c, static_cast<Eigen::Index>(i))), 1e12) << set.lambdaNm[i];
    }
  }
  EXPECT_LT(fitError(set, problem, cie).mean, 0.5);
}

// The Optimised strategy's sampler gives the fitted wavelengths every frame and the fitted matrix,
// not c̄/(n·pdf): its estimate is the fit's.
TEST(WavelengthFit, OptimisedSamplerUsesTheFittedSet) {
  const Observer& cie = observer("cie1931");
  const Spectrum f2 = illuminant("F2");
  const WavelengthFitProblem problem{{f2}, colourCheckerReflectances(), 8};
  const FittedWavelengths set = fitWavelengths(problem, cie);
  const WavelengthSampler sampler({8, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Optimised}, set);
  for (std::uint32_t seed : {0u, 7u}) {
    const std::vector<SampledWavelengths> batches = sampler.sample(seed);
    ASSERT_EQ(batches.size(), 2u);
    const std::vector<IntegrationMatrix> m = sampler.matrices(batches, cie);
    for (std::size_t i = 0; i < 8; ++i) {
      EXPECT_EQ(batches[i / 4].lambdaNm[i % 4], set.lambdaNm[i]);
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(m[i / 4](c, static_cast<Eigen::Index>(i % 4)), set.weights(c, static_cast<Eigen::Index>(i)));
    }
  }
}

TEST(WavelengthFit, IsCachedByItsInputs) {
  const Observer& cie = observer("cie1931");
  WavelengthFitProblem problem{{illuminant("A")}, colourCheckerReflectances(), 4};
  const FittedWavelengths fitted = cachedFitWavelengths(problem, cie);
  const FittedWavelengths cached = cachedFitWavelengths(problem, cie);
  EXPECT_EQ(fitted.lambdaNm, cached.lambdaNm);
  EXPECT_TRUE(fitted.weights.isApprox(cached.weights, 1e-15));
  WavelengthFitProblem other = problem;
  other.lights = {illuminant("D65")};
  EXPECT_NE(fitKey(problem, cie), fitKey(other, cie));
}

// An entry edited by hand or damaged is refitted, said in one line: a changed weight (its
// checksum differs), and a wavelength outside the range with the checksum made to match (before,
// both were used as they stood: λ 900 nm, weights of 1000).
TEST(WavelengthFit, AnEditedCacheEntryIsRefitted) {
  const Observer& cie = observer("cie1931");
  const WavelengthFitProblem problem{{illuminant("F2")}, colourCheckerReflectances(), 4};
  const FittedWavelengths fitted = cachedFitWavelengths(problem, cie);
  const std::filesystem::path path = cacheDirectory() / "wavelengths" / (std::to_string(fitKey(problem, cie)) + ".txt");
  std::ifstream in(path);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string body = good.substr(0, good.rfind("checksum "));
  std::string weight = good;
  weight[weight.find("weights ") + 8] = weight[weight.find("weights ") + 8] == '1' ? '2' : '1';
  const std::size_t lambda = body.find("lambda ") + 7;
  std::string outside = body.substr(0, lambda) + "900" + body.substr(body.find(' ', lambda));
  outside += "checksum " + std::to_string(fnv1a(outside.data(), outside.size())) + "\n";
  for (const std::string& edited : {weight, outside, good + "more\n"}) {
    std::ofstream(path, std::ios::trunc) << edited;
    ::testing::internal::CaptureStderr();
    const FittedWavelengths again = cachedFitWavelengths(problem, cie);
    EXPECT_NE(::testing::internal::GetCapturedStderr().find("is damaged"), std::string::npos) << edited;
    EXPECT_EQ(again.lambdaNm, fitted.lambdaNm);
  }
}

// A folder where the entry belongs: an Error naming it before any fit (reading it threw the
// stream's failure, `prism: internal error`), and the folder kept.
TEST(WavelengthFit, AFolderWhereTheCacheEntryBelongsIsAnError) {
  const ScopedCacheDirectory cache("prism_wavelength_fit_folder");
  const Observer& cie = observer("cie1931");
  const WavelengthFitProblem problem{{illuminant("F2")}, colourCheckerReflectances(), 4};
  const std::filesystem::path path = cacheDirectory() / "wavelengths" / (std::to_string(fitKey(problem, cie)) + ".txt");
  std::filesystem::create_directories(path);
  try {
    cachedFitWavelengths(problem, cie);
    FAIL() << "a folder in the entry's place was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder where the cache keeps a wavelength set"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_directory(path));
}

TEST(WavelengthFit, BadProblemsAreErrors) {
  const Observer& cie = observer("cie1931");
  EXPECT_THROW(fitWavelengths({{}, colourCheckerReflectances(), 4}, cie), Error);
  EXPECT_THROW(fitWavelengths({{illuminant("D65")}, {}, 4}, cie), Error);
  EXPECT_THROW(fitWavelengths({{illuminant("D65")}, colourCheckerReflectances(), 6}, cie), Error);
  EXPECT_THROW(fitWavelengths({{illuminant("D65")}, colourCheckerReflectances(), 4, 500, 502}, cie), Error);
  EXPECT_THROW(fitWavelengths({{Spectrum()}, colourCheckerReflectances(), 4}, cie), Error);
}

}  // namespace
}  // namespace prism

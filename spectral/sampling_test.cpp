#include "spectral/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "spectral/colour_checker.h"
#include "spectral/colour_difference.h"
#include "spectral/illuminant.h"

namespace prism {
namespace {

// XYZ of an emitter through the sampled estimator.
Eigen::Vector3d estimate(const SamplingSettings& s, std::uint32_t seed, const Spectrum& spd, const Observer& obs) {
  return WavelengthSampler(s, obs).estimate(seed, spd, obs);
}

// The strategies that need what this entry point lacks are a caller's error, not an abort.
TEST(Sampling, LightsAndOptimisedWithoutWhatTheyNeedAreAnError) {
  const Observer& cie = observer("cie1931");
  EXPECT_THROW(sampleWavelengths({16, 360, 830, SamplingStrategy::Lights}, 1, cie), Error);
  EXPECT_THROW(sampleWavelengths({16, 360, 830, SamplingStrategy::Optimised}, 1, cie), Error);
  EXPECT_THROW(WavelengthSampler({16, 360, 830, SamplingStrategy::Optimised}, cie, Spectrum::constant(1.0)), Error);
}

TEST(Sampling, Uniform400ReproducesThe1nmIntegralsOfD65) {
  const Observer& cie = observer("cie1931");
  Spectrum d65 = illuminant("D65");
  Eigen::Vector3d reference = cie.integrate(d65);
  Eigen::Vector3d sampled = estimate({400, 360, 830, SamplingStrategy::Uniform}, 0, d65, cie);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sampled[c] / reference[c], 1.0, 1e-3) << c;
}

TEST(Sampling, UniformUsesMidpointsInBatchesOfFour) {
  std::vector<SampledWavelengths> b =
      sampleWavelengths({8, 400, 480, SamplingStrategy::Uniform}, 7, observer("cie1931"));
  ASSERT_EQ(b.size(), 2u);
  EXPECT_DOUBLE_EQ(b[0].lambdaNm[0], 405.0);
  EXPECT_DOUBLE_EQ(b[1].lambdaNm[3], 475.0);
  EXPECT_DOUBLE_EQ(b[1].pdf[3], 1.0 / 80.0);
}

// ∫ s·c̄ exactly for s and c̄ piecewise linear between the 1 nm nodes, which is what a sampled
// estimator's expectation is (the trapezoid rule of Observer::integrate differs from it by
// −Σ Δs·Δc̄/6 over the nodes: −7.7e-5 of X for F11 × orange yellow).
Eigen::Vector3d exactIntegral(const Spectrum& s, const Observer& obs) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i + 1 < kSpectrumSamples; ++i) {
    for (int c = 0; c < 3; ++c) {
      double s0 = s[i], s1 = s[i + 1], c0 = obs.curves[static_cast<std::size_t>(c)][i],
             c1 = obs.curves[static_cast<std::size_t>(c)][i + 1];
      sum[c] += (2.0 * s0 * c0 + s0 * c1 + s1 * c0 + 2.0 * s1 * c1) / 6.0;
    }
  }
  return sum;
}

// The mean over many seeds within 3σ of the exact integral: the estimator is unbiased. The 3σ is
// printed beside the bias it allows, relative to the integral, so that a bound too loose to see a
// bias shows (16 wavelengths allow a tenth to a fifth of 4's: 0.05–0.5 % of the integral).
void expectUnbiased(SamplingStrategy strategy, int count) {
  const Observer& cie = observer("cie1931");
  Spectrum d65 = illuminant("D65");
  Eigen::Vector3d reference = exactIntegral(d65, cie);
  constexpr int kSeeds = 10000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sumSq = Eigen::Vector3d::Zero();
  for (int seed = 0; seed < kSeeds; ++seed) {
    Eigen::Vector3d e = estimate({count, 360, 830, strategy}, static_cast<std::uint32_t>(seed), d65, cie);
    sum += e;
    sumSq += e.cwiseProduct(e);
  }
  Eigen::Vector3d mean = sum / kSeeds;
  Eigen::Vector3d variance = sumSq / kSeeds - mean.cwiseProduct(mean);
  for (int c = 0; c < 3; ++c) {
    double sigmaOfMean = std::sqrt(variance[c] / (kSeeds - 1));
    std::printf("%d wavelengths, channel %d: mean / integral - 1 = %.2g, 3 sigma %.2g\n", count, c,
                mean[c] / reference[c] - 1.0, 3.0 * sigmaOfMean / reference[c]);
    EXPECT_GT(sigmaOfMean, 0.0);
    EXPECT_LE(std::abs(mean[c] - reference[c]), 3.0 * sigmaOfMean)
        << "channel " << c << ": mean " << mean[c] << " vs " << reference[c];
  }
}

TEST(Sampling, StratifiedIsUnbiased) {
  expectUnbiased(SamplingStrategy::Stratified, 4);
  expectUnbiased(SamplingStrategy::Stratified, 16);
}
TEST(Sampling, ImportanceIsUnbiased) {
  expectUnbiased(SamplingStrategy::Importance, 4);
  expectUnbiased(SamplingStrategy::Importance, 16);
}

TEST(Sampling, RotatedFramesConvergeFasterThanIndependentJitter) {
  // 16 wavelengths a frame, the mean of 64 frames: the rotated grid's error is far below the
  // independently jittered one's (both unbiased; the rotation fills the gaps evenly).
  const Observer& cie = observer("cie1931");
  Spectrum f11 = illuminant("F11");  // spiky: the hard case for few wavelengths
  Eigen::Vector3d reference = cie.integrate(f11);
  auto meanError = [&](SamplingStrategy strategy) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::uint32_t frame = 0; frame < 64; ++frame)
      sum += estimate({16, 360, 830, strategy}, frame, f11, cie);
    return (sum / 64.0 - reference).norm() / reference.norm();
  };
  double rotated = meanError(SamplingStrategy::Rotated);
  double jittered = meanError(SamplingStrategy::Stratified);
  EXPECT_LT(rotated, 0.01);
  EXPECT_LT(rotated, jittered / 2.0) << rotated << " vs " << jittered;
  EXPECT_EQ(sampleWavelengths({8, 400, 480, SamplingStrategy::Rotated}, 0, cie)[0].lambdaNm[0],
            sampleWavelengths({8, 400, 480, SamplingStrategy::Uniform}, 0, cie)[0].lambdaNm[0]);
}

TEST(Sampling, ImportanceSamplingFollowsTheObserver) {
  // More samples where x̄+ȳ+z̄ is large: none of 64 in the nearly dead 780–830 nm band.
  std::vector<SampledWavelengths> b =
      sampleWavelengths({64, 360, 830, SamplingStrategy::Importance}, 3, observer("cie1931"));
  for (const SampledWavelengths& w : b)
    for (double l : w.lambdaNm) EXPECT_LT(l, 780.0);
}

// XYZ of `light` × `reflectance` through a Lights sampler following `light`, one frame (seed).
Eigen::Vector3d estimateUnderLights(const WavelengthSampler& sampler, std::uint32_t seed, const Spectrum& radiance,
                                    const Observer& obs) {
  return sampler.estimate(seed, radiance, obs);
}

TEST(Sampling, LightsIsUnbiasedUnderASpikyLamp) {
  // F11's three narrow lines × ColorChecker orange yellow, 16 wavelengths a frame, the pdf
  // following F11: the mean of many frames (rotations) is the 1 nm integral. The expectation
  // over a uniform rotation is the integral exactly; 65536 golden-ratio rotations leave a
  // quasi-Monte Carlo error of a few 1e-6 (measured 3.2e-6 at most; 2.4e-5 after 4096).
  // A weight without the defensive mixture, or a pdf off by a bin, is off by percents.
  const Observer& cie = observer("cie1931");
  Spectrum f11 = illuminant("F11");
  Spectrum radiance = f11 * colourChecker()[11].reflectance;  // orange yellow
  Eigen::Vector3d reference = exactIntegral(radiance, cie);
  WavelengthSampler sampler({16, 360, 830, SamplingStrategy::Lights}, cie, f11);
  constexpr int kFrames = 65536;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::uint32_t frame = 0; frame < kFrames; ++frame) sum += estimateUnderLights(sampler, frame, radiance, cie);
  Eigen::Vector3d mean = sum / kFrames;
  std::printf("lights, mean of %d frames / 1 nm integral − 1: %.2g %.2g %.2g\n", kFrames, mean[0] / reference[0] - 1.0,
              mean[1] / reference[1] - 1.0, mean[2] / reference[2] - 1.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c] / reference[c], 1.0, 1e-5) << "channel " << c;
  // The trapezoid rule itself is within 1e-4 of the exact integral here.
  Eigen::Vector3d trapezoid = cie.integrate(radiance);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(trapezoid[c] / reference[c], 1.0, 1e-4) << "channel " << c;
}

TEST(Sampling, LightsIsCloseInOneFrameAndConvergesAsTheRotatedGrid) {
  // Under F11 the pdf ∝ F11·Σ c̄/∫F11·c̄ leaves the estimator only the smooth ρ·c̄/Σ(c̄/∫F11·c̄) to
  // integrate: one frame of 16 is far closer than the uniform grid's (measured 0.042 vs 0.67), and
  // 64 frames closer still, as the rotated grid converges, about as 1/frames (measured 1.0e-3,
  // the rotated uniform grid 7.9e-3).
  const Observer& cie = observer("cie1931");
  Spectrum f11 = illuminant("F11");
  Spectrum radiance = f11 * colourChecker()[11].reflectance;
  Eigen::Vector3d reference = cie.integrate(radiance);
  WavelengthSampler lights({16, 360, 830, SamplingStrategy::Lights}, cie, f11);
  WavelengthSampler rotated({16, 360, 830, SamplingStrategy::Rotated}, cie, f11);
  auto error = [&](const WavelengthSampler& sampler, int frames) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int f = 0; f < frames; ++f)
      sum += estimateUnderLights(sampler, static_cast<std::uint32_t>(f), radiance, cie);
    return (sum / frames - reference).norm() / reference.norm();
  };
  double lightsOne = error(lights, 1), rotatedOne = error(rotated, 1);
  double lightsMany = error(lights, 64), rotatedMany = error(rotated, 64);
  std::printf("relative error, 1 frame: lights %.2g, rotated %.2g; 64 frames: lights %.2g, rotated %.2g\n", lightsOne,
              rotatedOne, lightsMany, rotatedMany);
  EXPECT_LT(lightsOne, rotatedOne / 10.0) << lightsOne << " vs " << rotatedOne;
  EXPECT_LT(lightsMany, lightsOne / 16.0) << lightsMany << " after 64 frames, " << lightsOne << " after 1";
  EXPECT_LT(lightsMany, rotatedMany) << lightsMany << " vs " << rotatedMany;
}

TEST(Sampling, LightsFollowsANarrowLed) {
  // A 450 nm LED, 20 nm wide: 90 % of the pdf is the lamp's, so of 16 stratified wavelengths 13
  // or 14 fall within ±20 nm of its peak (ask for 12: its ȳ share goes a little beyond), where
  // Importance (the observer alone) puts 3 or 4.
  const Observer& cie = observer("cie1931");
  Spectrum led = illuminant("led:450:20");
  auto inBand = [&](SamplingStrategy strategy, std::uint32_t seed) {
    int count = 0;
    for (const SampledWavelengths& b : WavelengthSampler({16, 360, 830, strategy}, cie, led).sample(seed))
      for (double l : b.lambdaNm) count += (l >= 430.0 && l <= 470.0) ? 1 : 0;
    return count;
  };
  for (std::uint32_t seed = 0; seed < 8; ++seed) {
    std::printf("seed %u: %d of 16 within 430–470 nm (importance: %d)\n", seed, inBand(SamplingStrategy::Lights, seed),
                inBand(SamplingStrategy::Importance, seed));
    EXPECT_GE(inBand(SamplingStrategy::Lights, seed), 12) << seed;
    EXPECT_LE(inBand(SamplingStrategy::Importance, seed), 4) << seed;
  }
}

TEST(Sampling, OneFrameOfTheColourCheckerUnderEachLamp) {
  // What a single frame of 16 wavelengths shows, as a moving camera sees frame after frame: the
  // mean over 32 frames (rotations, or Importance's jitter seeds) of the ColorChecker's mean
  // ΔE00 from the 1 nm integral, in CIELAB of a D65 white at the lamp's white luminance (as
  // prism validate compares). The lights' pdf wins where the spectrum has lines or a narrow
  // band; under smooth lamps the uniform grid's midpoint rule is hard to beat, since its
  // integrand vanishes smoothly at both ends of the range while a warped one does not.
  const Observer& cie = observer("cie1931");
  auto oneFrameError = [&](const Spectrum& lamp, SamplingStrategy strategy) {
    WavelengthSampler sampler({16, 360, 830, strategy}, cie, lamp);
    const Eigen::Vector3d white = Eigen::Vector3d(0.95047, 1.0, 1.08883) * cie.integrate(lamp).y();
    double sum = 0.0;
    constexpr int kFrames = 32;
    for (std::uint32_t frame = 0; frame < kFrames; ++frame) {
      for (const ColourCheckerPatch& patch : colourChecker()) {
        Spectrum radiance = lamp * patch.reflectance;
        sum += deltaE(xyzToLab(estimateUnderLights(sampler, frame, radiance, cie), white),
                      xyzToLab(cie.integrate(radiance), white), DeltaEFormula::Ciede2000);
      }
    }
    return sum / (kFrames * static_cast<double>(colourChecker().size()));
  };
  std::printf("%-14s %8s %10s %8s\n", "lamp", "rotated", "importance", "lights");
  for (const char* name : {"D65", "A", "led-globe-a19", "led:450:20", "F2", "F11"}) {
    Spectrum lamp = illuminant(name);
    double rotated = oneFrameError(lamp, SamplingStrategy::Rotated);
    double importance = oneFrameError(lamp, SamplingStrategy::Importance);
    double lights = oneFrameError(lamp, SamplingStrategy::Lights);
    std::printf("%-14s %8.2f %10.2f %8.2f\n", name, rotated, importance, lights);
    const std::string lampName = name;
    if (lampName == "led:450:20" || lampName == "F2" || lampName == "F11") {
      EXPECT_LT(lights, rotated / 2.0) << name;
    }
  }
}

TEST(Sampling, SeedsChangeStratifiedWavelengths) {
  const Observer& cie = observer("cie1931");
  auto a = sampleWavelengths({4, 360, 830, SamplingStrategy::Stratified}, 1, cie);
  auto b = sampleWavelengths({4, 360, 830, SamplingStrategy::Stratified}, 2, cie);
  EXPECT_NE(a[0].lambdaNm, b[0].lambdaNm);
  for (int i = 0; i < 4; ++i) {  // each stays in its stratum
    EXPECT_GE(a[0].lambdaNm[static_cast<std::size_t>(i)], 360.0 + i * 117.5);
    EXPECT_LT(a[0].lambdaNm[static_cast<std::size_t>(i)], 360.0 + (i + 1) * 117.5);
  }
}

TEST(Sampling, InvalidSettingsAreErrors) {
  EXPECT_THROW(validate({6, 360, 830, SamplingStrategy::Uniform}), Error);
  EXPECT_THROW(validate({0, 360, 830, SamplingStrategy::Uniform}), Error);
  EXPECT_THROW(validate({1004, 360, 830, SamplingStrategy::Uniform}), Error);
  EXPECT_THROW(validate({16, 350, 830, SamplingStrategy::Uniform}), Error);
  EXPECT_THROW(validate({16, 400, 900, SamplingStrategy::Uniform}), Error);
  EXPECT_THROW(validate({16, 500, 500, SamplingStrategy::Uniform}), Error);
  EXPECT_NO_THROW(validate({1000, 380, 780, SamplingStrategy::Stratified}));
  EXPECT_THROW(samplingStrategyFromName("random"), Error);
  for (SamplingStrategy s : {SamplingStrategy::Uniform, SamplingStrategy::Stratified, SamplingStrategy::Rotated,
                             SamplingStrategy::Importance, SamplingStrategy::Lights})
    EXPECT_EQ(samplingStrategyFromName(samplingStrategyName(s)), s);
}

TEST(Sampling, AnOptimisedSetTakesEveryWholeNanometreOfItsRangeEndsIncluded) {
  // The fit's nodes are the whole nanometres of the range, both ends included: 500–503 holds 4
  // (it was refused as holding fewer), 500–502.9 and 500.1–503 hold 3.
  EXPECT_NO_THROW(validate({4, 500, 503, SamplingStrategy::Optimised}));
  EXPECT_NO_THROW(validate({4, 499.5, 503, SamplingStrategy::Optimised}));
  EXPECT_THROW(validate({4, 500, 502.9, SamplingStrategy::Optimised}), Error);
  EXPECT_THROW(validate({4, 500.1, 503, SamplingStrategy::Optimised}), Error);
}

}  // namespace
}  // namespace prism

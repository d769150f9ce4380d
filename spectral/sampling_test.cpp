#include "spectral/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "spectral/illuminant.h"

namespace prism {
namespace {

// XYZ of an emitter through the sampled estimator.
Eigen::Vector3d estimate(const SamplingSettings& s, std::uint32_t seed, const Spectrum& spd,
                         const Observer& obs) {
  std::vector<SampledWavelengths> batches = sampleWavelengths(s, seed, obs);
  std::vector<IntegrationMatrix> m = integrationMatrices(batches, obs);
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < batches.size(); ++b) {
    Eigen::Vector4d radiance;
    for (int j = 0; j < 4; ++j) radiance[j] = spd.at(batches[b].lambdaNm[static_cast<std::size_t>(j)]);
    xyz += m[b] * radiance;
  }
  return xyz;
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

// Mean over many seeds within 3σ of the 1 nm value: the estimator is unbiased.
void expectUnbiased(SamplingStrategy strategy, int count) {
  const Observer& cie = observer("cie1931");
  Spectrum d65 = illuminant("D65");
  Eigen::Vector3d reference = cie.integrate(d65);
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
    EXPECT_GT(sigmaOfMean, 0.0);
    EXPECT_LE(std::abs(mean[c] - reference[c]), 3.0 * sigmaOfMean)
        << "channel " << c << ": mean " << mean[c] << " vs " << reference[c];
  }
}

TEST(Sampling, StratifiedIsUnbiased) { expectUnbiased(SamplingStrategy::Stratified, 4); }
TEST(Sampling, ImportanceIsUnbiased) { expectUnbiased(SamplingStrategy::Importance, 4); }

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
}

}  // namespace
}  // namespace prism

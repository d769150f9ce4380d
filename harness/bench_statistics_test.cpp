#include "harness/bench_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

namespace prism::harness {
namespace {

TEST(BenchStatistics, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(median({}), 0.0);
  EXPECT_EQ(median({7.0}), 7.0);
  EXPECT_EQ(median({5.0, 1.0, 3.0}), 3.0);          // unsorted input
  EXPECT_EQ(median({4.0, 1.0, 3.0, 100.0}), 3.5);   // mean of the middle two, outlier ignored
}

TEST(BenchStatistics, RatiosAreTakenWithinARoundBeforeTheMedian) {
  // The load doubles in round 2: both sides slow down together, the ratio does not move.
  RatioSpread s = perRoundRatios({12.0, 24.0, 13.0}, {10.0, 20.0, 10.0});
  EXPECT_DOUBLE_EQ(s.median, 1.2);
  EXPECT_DOUBLE_EQ(s.min, 1.2);
  EXPECT_DOUBLE_EQ(s.max, 1.3);
  EXPECT_TRUE(std::isnan(s.confidence.low));  // three rounds are too few for 95 %
  // Medians first, then the ratio, would have said 13 / 10 = 1.3.
  EXPECT_NE(s.median, median({12.0, 24.0, 13.0}) / median({10.0, 20.0, 10.0}));
  EXPECT_THROW(perRoundRatios({1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(perRoundRatios({}, {}), std::invalid_argument);
}

TEST(BenchStatistics, TheMedianIntervalTakesTheBinomialRanks) {
  // n = 20: P(B ≤ 5) = 0.0207 ≤ 0.025 < P(B ≤ 6) = 0.0577, so x₍₆₎ and x₍₁₅₎ (tables of the sign test).
  std::vector<double> twenty(20);
  std::iota(twenty.begin(), twenty.end(), 1.0);
  std::shuffle(twenty.begin(), twenty.end(), std::mt19937(7));
  Interval i20 = medianConfidenceInterval(twenty);
  EXPECT_EQ(i20.low, 6.0);
  EXPECT_EQ(i20.high, 15.0);
  // n = 6: 1/64 ≤ 0.025, so the extremes; n = 5: 1/32 > 0.025, none at 95 %, one at 90 %.
  Interval i6 = medianConfidenceInterval({3, 1, 4, 1.5, 9, 2.6});
  EXPECT_EQ(i6.low, 1.0);
  EXPECT_EQ(i6.high, 9.0);
  EXPECT_TRUE(std::isnan(medianConfidenceInterval({1, 2, 3, 4, 5}).low));
  EXPECT_EQ(medianConfidenceInterval({1, 2, 3, 4, 5}, 0.9).high, 5.0);
  EXPECT_TRUE(std::isnan(medianConfidenceInterval({}).high));
  EXPECT_THROW(medianConfidenceInterval({1, 2}, 1.0), std::invalid_argument);
}

TEST(BenchStatistics, TheMedianIntervalCoversTheMedianAsOftenAsItSays) {
  // 30 draws from a skewed distribution (exponential, median ln 2): x₍₁₀₎..x₍₂₁₎ cover it with
  // probability 1 − 2·P(B ≤ 9) = 0.9572; 4000 trials put the observed rate within ±0.0032 (1σ).
  std::mt19937 rng(2026);
  std::exponential_distribution<double> draw(1.0);
  int covered = 0;
  const int trials = 4000;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> v(30);
    for (double& x : v) x = draw(rng);
    Interval i = medianConfidenceInterval(v);
    covered += i.low <= std::log(2.0) && std::log(2.0) <= i.high;
  }
  EXPECT_NEAR(covered / double(trials), 0.9572, 0.012);  // ±3.7σ
}

TEST(BenchStatistics, LinearFitRecoversALineAndTheLeastSquaresSlope) {
  LinearFit exact = linearFit({4, 8, 16, 32}, {3.2, 4.4, 6.8, 11.6});  // 0.3·n + 2
  EXPECT_NEAR(exact.slope, 0.3, 1e-12);
  EXPECT_NEAR(exact.intercept, 2.0, 1e-12);
  // Not on a line: Sxy / Sxx = 4 / 5, through the means (1.5, 1.5).
  LinearFit noisy = linearFit({0, 1, 2, 3}, {0.5, 0.5, 2.5, 2.5});
  EXPECT_NEAR(noisy.slope, 0.8, 1e-12);
  EXPECT_NEAR(noisy.intercept, 0.3, 1e-12);
  LinearFit flat = linearFit({16, 16}, {5.0, 7.0});
  EXPECT_EQ(flat.slope, 0.0);
  EXPECT_EQ(flat.intercept, 6.0);
}

}  // namespace
}  // namespace prism::harness

#include "harness/bench_statistics.h"

#include <gtest/gtest.h>

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
  // Medians first, then the ratio, would have said 13 / 10 = 1.3.
  EXPECT_NE(s.median, median({12.0, 24.0, 13.0}) / median({10.0, 20.0, 10.0}));
  EXPECT_THROW(perRoundRatios({1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(perRoundRatios({}, {}), std::invalid_argument);
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

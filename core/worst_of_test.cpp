#include "core/worst_of.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace prism {
namespace {

TEST(WorstOf, IsTheLargerOfFiniteErrors) {
  EXPECT_EQ(worstOf(0.0, 0.5), 0.5);
  EXPECT_EQ(worstOf(0.5, 0.25), 0.5);
}

TEST(WorstOf, ANonFiniteErrorStaysInfiniteWhateverFollows) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  double worst = 0.0;
  for (double e : {0.1, nan, 0.2}) worst = worstOf(worst, e);
  EXPECT_EQ(worst, inf);
  EXPECT_EQ(worstOf(0.0, -inf), inf);
  EXPECT_EQ(worstOf(inf, 0.3), inf);
}

}  // namespace
}  // namespace prism

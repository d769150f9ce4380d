// The progress bar's estimate of the time left: extrapolated from the rate so far, said in the
// unit a reader wants, and not said when there is nothing to extrapolate from.
#include "harness/progress_bar.h"

#include <gtest/gtest.h>

namespace prism::harness {
namespace {

TEST(ProgressBar, TimeLeftIsTheRateSoFarOverWhatRemains) {
  EXPECT_EQ(timeLeftText(1, 4, 10.0), "about 30 s left");
  EXPECT_EQ(timeLeftText(3, 4, 10.0), "about 3 s left");
  EXPECT_EQ(timeLeftText(99, 100, 2.0), "about 1 s left");  // never "0 s" while work remains
  EXPECT_EQ(timeLeftText(1, 100, 60.0), "about 99 min left");
  EXPECT_EQ(timeLeftText(1, 100, 61.0), "about 1.7 h left");
  EXPECT_EQ(timeLeftText(10, 11, 990.0), "about 99 s left");
  EXPECT_EQ(timeLeftText(10, 11, 1000.0), "about 2 min left");
  EXPECT_EQ(timeLeftText(1, 2, 6000.0), "about 1.7 h left");
}

TEST(ProgressBar, NoEstimateBeforeASecondOrWithoutWorkDoneOrLeft) {
  EXPECT_EQ(timeLeftText(0, 4, 10.0), "");
  EXPECT_EQ(timeLeftText(4, 4, 10.0), "");
  EXPECT_EQ(timeLeftText(5, 4, 10.0), "");
  EXPECT_EQ(timeLeftText(1, 4, 0.5), "");
  EXPECT_EQ(timeLeftText(0, 0, 10.0), "");
}

}  // namespace
}  // namespace prism::harness

// The atmosphere commands' options: --quick's defaults give way to what is given.
#include <gtest/gtest.h>

#include "core/error.h"
#include "harness/sky_experiments.h"

namespace prism::harness {
namespace {

TEST(SkyRun, QuickKeepsWhatIsGiven) {
  AtmosphereCommandOptions o;
  SkyRun run = skyRunOf(o);
  EXPECT_EQ(run.referenceStepNm, 1.0);
  EXPECT_EQ(run.zeniths, 16);
  EXPECT_EQ(run.azimuths, 32);
  o.quick = true;
  run = skyRunOf(o);
  EXPECT_EQ(run.referenceStepNm, 10.0);
  EXPECT_EQ(run.zeniths, 8);
  EXPECT_EQ(run.azimuths, 16);
  // Before, --quick replaced these silently (a user's --quick --reference-step 50 ran at 10 nm).
  o.referenceStepNm = 50.0;
  o.zeniths = 1;
  o.azimuths = 2;
  run = skyRunOf(o);
  EXPECT_EQ(run.referenceStepNm, 50.0);
  EXPECT_EQ(run.zeniths, 1);
  EXPECT_EQ(run.azimuths, 2);
  o.zeniths = 0;
  EXPECT_THROW(skyRunOf(o), Error);
}

}  // namespace
}  // namespace prism::harness

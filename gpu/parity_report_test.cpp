// The yardstick of the parity tests: ULP distances, GLSL's pow bound, and a negative control
// showing that a formula that differs slightly from the CPU's is caught.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "sigmoid.glsl"
}

namespace prism::gpu {
namespace {

using testing::GpuTest;

TEST(ParityReport, UlpDistanceCountsRepresentableFloatsAcrossZero) {
  EXPECT_EQ(testing::ulpDistance(1.0f, 1.0f), 0);
  EXPECT_EQ(testing::ulpDistance(1.0f, std::nextafter(1.0f, 2.0f)), 1);
  EXPECT_EQ(testing::ulpDistance(0.0f, -0.0f), 0);
  float tiny = std::numeric_limits<float>::denorm_min();
  EXPECT_EQ(testing::ulpDistance(tiny, -tiny), 2);
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(testing::ulpDistance(inf, inf), 0);
  EXPECT_EQ(testing::ulpDistance(inf, -inf), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(testing::ulpDistance(1.0f, std::numeric_limits<float>::quiet_NaN()),
            std::numeric_limits<std::int64_t>::max());
}

TEST(ParityReport, GlslPowBoundFollowsTheSpecTable) {
  // x in [0.5, 2]: log2 within 2^-21 absolute; y·log2 x = 0 gives exp2's 3 ULP.
  EXPECT_NEAR(testing::glslPowRelativeError(1.0, 2.4),
              3.0 * testing::kUlp + 2.4 * 0x1p-21 * std::log(2.0), 1e-12);
  // Far from 1 the exp2 term 2·|y·log2 x| ULP dominates.
  EXPECT_GT(testing::glslPowRelativeError(1.0 / 256.0, 2.4),
            (3.0 + 2.0 * 2.4 * 8.0) * testing::kUlp);
}

// A GPU result held to the CPU's with its real tolerance must fail when the CPU side computes
// something slightly different (here S at x·(1 + 1e-5), a change of at most ≈ 2e-6).
TEST_F(GpuTest, NegativeControlAFormulaThatDiffersSlightlyFails) {
  std::vector<float> x;
  testing::InputGenerator gen(0xc047401u);
  while (x.size() < 1024) x.push_back(gen.uniform(-4.0f, 4.0f));
  Program kernel = testing::parityKernel("sigmoid.comp", {{"SIGMOID_FUNCTION", "sigmoid"}});
  std::vector<float> gpu = testing::runParityKernel<float>(kernel, std::span<const float>(x));
  testing::ParityReport report("sigmoid (control)", {6.7e-7, 0.0, 0});  // sigmoid's own
  for (std::size_t i = 0; i < x.size(); ++i)
    report.compare(gpu[i], shared::sigmoid(x[i] * (1.0f + 1e-5f)), "control");
  EXPECT_NONFATAL_FAILURE(report.finish(), "values outside tolerance");
  EXPECT_GT(report.maxAbsolute(), 6.7e-7);
}

}  // namespace
}  // namespace prism::gpu

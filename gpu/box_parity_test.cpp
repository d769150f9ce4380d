// box_upsampling.glsl on the GPU vs the same file compiled as C++.
#include <gtest/gtest.h>

#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "box_upsampling.glsl"
}

namespace prism::gpu {
namespace {

using testing::GpuTest;

// Tolerance: exact. Reason: the function only compares λ with two constants and selects a
// channel; wavelengths include both thresholds and their float neighbours.
TEST_F(GpuTest, BoxReflectance4IsExact) {
  testing::InputGenerator gen(0xb0c5u);
  std::vector<glm::vec4> rgbs, lambdas;
  const float edges[] = {shared::kBoxBlueGreenNm, shared::kBoxGreenRedNm};
  for (float e : edges) {
    rgbs.push_back({0.1f, 0.5f, 0.9f, 0.0f});
    lambdas.push_back({std::nextafter(e, 0.0f), e, std::nextafter(e, 1e4f), 360.0f});
  }
  while (rgbs.size() < 4096) {
    rgbs.push_back({gen.uniform(0.0f, 1.0f), gen.uniform(0.0f, 1.0f), gen.uniform(0.0f, 1.0f), 0.0f});
    lambdas.push_back({gen.uniform(360.0f, 830.0f), gen.uniform(360.0f, 830.0f),
                       gen.uniform(360.0f, 830.0f), gen.uniform(360.0f, 830.0f)});
  }
  Program kernel = testing::parityKernel("box_reflectance.comp");
  std::vector<glm::vec4> gpu = testing::runParityKernel<glm::vec4>(
      kernel, std::span<const glm::vec4>(rgbs), std::span<const glm::vec4>(lambdas));
  ASSERT_EQ(gpu.size(), rgbs.size());
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < rgbs.size(); ++i) {
    glm::vec4 cpu = shared::boxReflectance4(glm::vec3(rgbs[i]), lambdas[i]);
    if (gpu[i] != cpu && mismatches++ == 0)
      ADD_FAILURE() << "boxReflectance4 at λ (" << lambdas[i].x << ", " << lambdas[i].y << ", "
                    << lambdas[i].z << ", " << lambdas[i].w << ")";
  }
  std::printf("parity boxReflectance4 N=%zu mismatches %zu\n", rgbs.size(), mismatches);
  EXPECT_EQ(mismatches, 0u);
}

}  // namespace
}  // namespace prism::gpu

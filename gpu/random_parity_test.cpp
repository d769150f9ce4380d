// random.glsl on the GPU vs the same file compiled as C++: integer arithmetic, so bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "random.glsl"
}

namespace prism::gpu {
namespace {

using testing::GpuTest;

// Tolerance: exact (0 ULP). Reason: pcgHash is 32-bit unsigned multiply, add, shift and xor,
// defined modulo 2^32 in both languages; randomFloat converts a 24-bit integer (exact in
// float) and scales by 2^-24 (exact).
TEST_F(GpuTest, PcgHashAndRandomFloatAreBitExact) {
  testing::InputGenerator gen(0x5eed0001u);
  std::vector<glm::uvec4> args;
  // Edge values first: 0, 1, the top bit, all ones, and values whose hash state wraps.
  for (std::uint32_t v : {0u, 1u, 2u, 0x7fffffffu, 0x80000000u, 0xfffffffeu, 0xffffffffu,
                          2891336453u, 0u - 2891336453u})
    args.push_back({v, ~v, v, 0u});
  while (args.size() < 8192) args.push_back({gen.bits(), gen.bits() & 0xffffu, gen.bits(), 0u});

  Program kernel = testing::parityKernel("random.comp");
  std::vector<glm::uvec4> gpu =
      testing::runParityKernel<glm::uvec4>(kernel, std::span<const glm::uvec4>(args));
  ASSERT_EQ(gpu.size(), args.size());
  std::size_t hashMismatches = 0, floatMismatches = 0, unitMismatches = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::uint32_t hash = shared::pcgHash(args[i].z);
    std::uint32_t random = std::bit_cast<std::uint32_t>(shared::randomFloat(args[i].x, args[i].y));
    std::uint32_t unit = std::bit_cast<std::uint32_t>(shared::uintToUnitFloat(args[i].z));
    if (gpu[i].x != hash && hashMismatches++ == 0)
      ADD_FAILURE() << "pcgHash(" << args[i].z << "): gpu " << gpu[i].x << " cpu " << hash;
    if (gpu[i].y != random && floatMismatches++ == 0)
      ADD_FAILURE() << "randomFloat(" << args[i].x << ", " << args[i].y << "): gpu bits "
                    << gpu[i].y << " cpu bits " << random;
    if (gpu[i].z != unit && unitMismatches++ == 0)
      ADD_FAILURE() << "uintToUnitFloat(" << args[i].z << "): gpu bits " << gpu[i].z << " cpu bits "
                    << unit;
  }
  std::printf("parity pcgHash/randomFloat/uintToUnitFloat N=%zu mismatches %zu/%zu/%zu\n",
              args.size(), hashMismatches, floatMismatches, unitMismatches);
  EXPECT_EQ(hashMismatches + floatMismatches + unitMismatches, 0u);
  // A reference value pins the CPU side too (Jarzynski & Olano's pcg of 0 and 1).
  EXPECT_EQ(shared::pcgHash(0u), 129708002u);
}

}  // namespace
}  // namespace prism::gpu

#include "gpu/buffer.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gpu/error.h"
#include "gpu/gpu_test_support.h"
#include "gpu/object_counter.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

TEST_F(GpuTest, BufferRoundTripsDataAndUploadsRanges) {
  std::vector<std::uint32_t> values(1000);
  for (std::uint32_t i = 0; i < values.size(); ++i) values[i] = i * 2654435761u;
  Buffer buffer = Buffer::fromSpan(std::span<const std::uint32_t>(values), "round trip");
  EXPECT_NE(buffer.id(), 0u);
  EXPECT_EQ(buffer.sizeBytes(), values.size() * 4);
  EXPECT_EQ(buffer.read<std::uint32_t>(), values);

  std::array<std::uint32_t, 2> patch{7u, 9u};
  buffer.upload(8, std::as_bytes(std::span(patch)));
  std::vector<std::uint32_t> back = buffer.read<std::uint32_t>();
  EXPECT_EQ(back[1], values[1]);
  EXPECT_EQ(back[2], 7u);
  EXPECT_EQ(back[3], 9u);
  EXPECT_EQ(back[4], values[4]);
}

TEST_F(GpuTest, BufferWithoutDataStartsZeroed) {
  Buffer buffer({13, nullptr, GL_DYNAMIC_STORAGE_BIT, "odd size"});
  std::vector<std::uint8_t> bytes = buffer.read<std::uint8_t>();
  EXPECT_EQ(bytes, std::vector<std::uint8_t>(13, 0));
}

TEST_F(GpuTest, BufferIsMoveOnlyAndFreesItsName) {
  std::array<float, 4> v{1.0f, 2.0f, 3.0f, 4.0f};
  Buffer a = Buffer::fromSpan(std::span<const float>(v));
  GLuint name = a.id();
  Buffer b(std::move(a));
  EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  EXPECT_EQ(b.id(), name);
  Buffer c;
  c = std::move(b);
  EXPECT_EQ(c.id(), name);
  EXPECT_TRUE(glIsBuffer(name));
  c = Buffer();
  EXPECT_FALSE(glIsBuffer(name));
  static_assert(!std::is_copy_constructible_v<Buffer>);
}

TEST_F(GpuTest, BufferRangesAreChecked) {
  Buffer buffer({16, nullptr, GL_DYNAMIC_STORAGE_BIT, {}});
  std::array<std::byte, 8> bytes{};
  EXPECT_THROW(buffer.upload(12, bytes), std::out_of_range);
  EXPECT_THROW(buffer.download(9, bytes), std::out_of_range);
  EXPECT_THROW(buffer.download(std::size_t(-4), bytes), std::out_of_range);
  EXPECT_NO_THROW(buffer.download(8, bytes));
  using Vec3 = std::array<float, 3>;
  EXPECT_THROW(buffer.read<Vec3>(), std::invalid_argument);  // 16 bytes ≠ k·12
  EXPECT_THROW(Buffer({0, nullptr, GL_DYNAMIC_STORAGE_BIT, {}}), std::invalid_argument);
}

// A buffer no GPU holds (a tebibyte) is one GpuError naming it, with no driver message before it
// and no GL object left behind: it went on as a broken buffer after the driver's KHR_debug line,
// and the command that wanted it ended in an internal error.
TEST_F(GpuTest, StorageNoGpuHoldsIsOneErrorNamingTheBuffer) {
  const GlObjectCounts start = liveGlObjects();
  try {
    Buffer huge({std::size_t{1} << 40, nullptr, 0, "huge"});
    ADD_FAILURE() << "a buffer of a tebibyte was made";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::BufferStorageFailed);
    EXPECT_EQ(std::string(e.what()).rfind("prism::gpu::Buffer 'huge' of 1099511627776 bytes: out of GPU memory", 0), 0u)
        << e.what();
  }
  EXPECT_EQ(liveGlObjects(), start);
}

}  // namespace
}  // namespace prism::gpu

// The live-object registry: every wrapper counts what it creates and uncounts what it deletes,
// through moves and move-assignments, so that a scope's counts return to where they began.
#include "gpu/object_counter.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "gpu/error.h"
#include "gpu/framebuffer.h"
#include "gpu/gpu_test_support.h"
#include "gpu/texture.h"
#include "gpu/timer_query.h"
#include "gpu/vertex_array.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

TEST_F(GpuTest, WrappersCountTheirObjectsBackToTheStart) {
  const GlObjectCounts start = liveGlObjects();
  auto grew = [&](GlObjectKind kind) { return liveGlObjects()[kind] - start[kind]; };
  {
    std::array<float, 4> values{1.0f, 2.0f, 3.0f, 4.0f};
    Buffer a = Buffer::fromSpan(std::span<const float>(values));
    Buffer b = Buffer::fromSpan(std::span<const float>(values));
    EXPECT_EQ(grew(GlObjectKind::Buffer), 2);
    a = std::move(b);  // deletes a's first name
    EXPECT_EQ(grew(GlObjectKind::Buffer), 1);
    Buffer c(std::move(a));  // moves count nothing
    EXPECT_EQ(grew(GlObjectKind::Buffer), 1);

    Texture2D colour({4, 4, GL_RGBA8, 1, {}, {}, {}});
    Texture2DArray depth({4, 4, 2, GL_DEPTH_COMPONENT32F, 1, false, {}, {}});
    Texture3D volume({1, 1, 1, GL_RGBA32F, GL_RGBA, values, {}});
    EXPECT_EQ(grew(GlObjectKind::Texture), 3);
    DepthAttachment layer{nullptr, &depth, 1, 0};
    Framebuffer fb({{{&colour, 0}}, layer, {}});
    EXPECT_EQ(grew(GlObjectKind::Framebuffer), 1);
    VertexArray vao = VertexArray::attributeless();
    EXPECT_EQ(grew(GlObjectKind::VertexArray), 1);
    Program program = testing::parityKernel("uniforms.comp");
    EXPECT_EQ(grew(GlObjectKind::Program), 1);
    GpuTimer timer;
    timer.beginFrame();
    {
      auto scope = timer.scope("clear");
      fb.clearColour(0, glm::vec4(0.0f));
    }
    timer.endFrame();
    EXPECT_EQ(grew(GlObjectKind::Query), 4);  // frame start and end, scope start and end
    EXPECT_GT(liveGlObjects().total(), start.total());
    std::string text = describeGlObjects(liveGlObjects());
    EXPECT_NE(text.find("vertex arrays "), std::string::npos) << text;
  }
  EXPECT_EQ(liveGlObjects(), start)
      << describeGlObjects(liveGlObjects()) << " vs " << describeGlObjects(start);
}

TEST_F(GpuTest, FailedConstructionsLeaveNothingCounted) {
  const GlObjectCounts start = liveGlObjects();
  Texture2D depth({4, 4, GL_DEPTH_COMPONENT32F, 1, {}, {}, {}});
  EXPECT_THROW(Framebuffer({{{&depth, 0}}, {}, {}}), GpuError);  // incomplete
  std::array<std::uint8_t, 3> tooFew{};
  TextureData data{GL_RGBA, GL_UNSIGNED_BYTE, std::as_bytes(std::span(tooFew))};
  EXPECT_THROW(Texture2D({2, 2, GL_RGBA8, 1, data, {}, {}}), std::invalid_argument);
  takeDebugErrors();
  EXPECT_THROW(testing::parityKernel("no_such_kernel.comp"), GpuError);
  ProgramDesc unlinkable;  // compiles, then fails to link: the program name is deleted
  unlinkable.compute = testing::testDirectory() / "loader" / "no_main.comp";
  unlinkable.includeDirs = testing::sharedIncludeDirs();
  EXPECT_THROW(Program{unlinkable}, GpuError);
  takeDebugErrors();
  depth = Texture2D();
  EXPECT_EQ(liveGlObjects(), start) << describeGlObjects(liveGlObjects());
}

}  // namespace
}  // namespace prism::gpu

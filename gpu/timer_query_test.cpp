// GPU timers: a frame's scopes come back finite, non-negative, in order, and inside the frame;
// results arrive framesInFlight frames later without asking, or at once through resolve().
#include "gpu/timer_query.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "gpu/framebuffer.h"
#include "gpu/gpu_test_support.h"
#include "gpu/vertex_array.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

TEST_F(GpuTest, TimerScopesAreFiniteNonNegativeAndWithinTheFrame) {
  Texture2D colour({64, 64, GL_RGBA32F, 1, {}, {}, "timed target"});
  Texture2D ids({64, 64, GL_R32UI, 1, {}, {}, "timed ids"});
  Framebuffer fb({{{&colour, 0}, {&ids, 0}}, {}, {}});
  Program draw = testing::drawProgram("fullscreen.vert", "two_targets.frag");
  draw.setUniform("uColour", glm::vec4(1.0f));
  draw.setUniform("uIdOffset", 0u);
  VertexArray empty = VertexArray::attributeless();
  Texture2D image({64, 64, GL_RGBA32F, 1, {}, {}, "timed image"});
  Program compute = testing::parityKernel("image_store.comp");

  GpuTimer timer({2});
  EXPECT_FALSE(timer.available());
  EXPECT_TRUE(timer.resolve().empty());
  for (int frame = 0; frame < 4; ++frame) {
    timer.beginFrame();  // from frame 2 on, reads frame - 2 into latest()
    EXPECT_EQ(timer.latest().empty(), frame < 2) << "frame " << frame;
    {
      auto scope = timer.scope("draw");
      fb.bind();
      draw.use();
      empty.draw(3);
    }
    {
      auto scope = timer.scope("compute");
      image.bindImage(0, GL_WRITE_ONLY);
      runCompute(compute, {64, 64, 1}, GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
    timer.endFrame();
  }
  glFinish();
  EXPECT_TRUE(timer.available());
  GpuTimings timings = timer.resolve();
  ASSERT_EQ(timings.size(), 3u);
  EXPECT_EQ(timings[0].first, "frame");
  EXPECT_EQ(timings[1].first, "draw");
  EXPECT_EQ(timings[2].first, "compute");
  double scopes = 0.0;
  for (const auto& [name, ms] : timings) {
    EXPECT_TRUE(std::isfinite(ms)) << name;
    EXPECT_GE(ms, 0.0) << name;
    std::printf("gpu timer: %-8s %.4f ms\n", name.c_str(), ms);
    if (name != "frame") scopes += ms;
  }
  // Sequential scopes inside one frame: exact in nanoseconds, up to rounding in milliseconds.
  EXPECT_LE(scopes, timings[0].second + 1e-9);
  EXPECT_EQ(timer.resolve(), timings);   // read once, kept
  EXPECT_EQ(timer.latest().size(), 3u);  // frame 1's, read at the start of frame 3
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GpuTest, TimerRejectsCallsOutOfOrder) {
  EXPECT_THROW(GpuTimer({1}), std::invalid_argument);
  GpuTimer timer;
  EXPECT_THROW(timer.beginScope("outside"), std::logic_error);
  EXPECT_THROW(timer.endFrame(), std::logic_error);
  timer.beginFrame();
  EXPECT_THROW(timer.beginFrame(), std::logic_error);
  EXPECT_THROW(timer.endScope(), std::logic_error);
  timer.beginScope("outer");
  timer.beginScope("inner");
  timer.endScope();
  EXPECT_THROW(timer.endFrame(), std::logic_error);  // "outer" still open
  timer.endScope();
  timer.endFrame();
  GpuTimings timings = timer.resolve();
  ASSERT_EQ(timings.size(), 3u);
  EXPECT_LE(timings[2].second, timings[1].second + 1e-9);  // nested inside "outer"
}

}  // namespace
}  // namespace prism::gpu

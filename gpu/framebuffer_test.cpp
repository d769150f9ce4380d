// Framebuffers through the driver: a draw reaches every pixel of each colour attachment, a
// depth layer of an array is a render target of its own, blits copy depth and colour, and an
// incomplete framebuffer is refused with its GL status.
#include "gpu/framebuffer.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/error.h"
#include "gpu/gpu_test_support.h"
#include "gpu/vertex_array.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

// A colour and an id target, and a program that draws (0.25, -1.5, 8, 1) into the first and
// 7 + x + 1000·y into the second over a full-screen triangle; bound and cleared to 0.
struct TwoTargets {
  TwoTargets(GLsizei w, GLsizei h)
      : colour({w, h, GL_RGBA32F, 1, {}, {}, "colour"}),
        ids({w, h, GL_R32UI, 1, {}, {}, "pixel ids"}),
        fb({{{&colour, 0}, {&ids, 0}}, {}, "two targets"}),
        program(testing::drawProgram("fullscreen.vert", "two_targets.frag")),
        triangle(VertexArray::attributeless("full-screen triangle")) {
    program.setUniform("uColour", glm::vec4(0.25f, -1.5f, 8.0f, 1.0f));
    program.setUniform("uIdOffset", 7u);
    fb.bind();
    fb.clearColour(0, glm::vec4(0.0f));
    fb.clearColourUint(1, {0u, 0u, 0u, 0u});
  }
  void draw() const {
    program.use();
    triangle.draw(3);
  }
  Texture2D colour, ids;
  Framebuffer fb;
  Program program;
  VertexArray triangle;
};

TEST_F(GpuTest, FullScreenTriangleFillsBothAttachments) {
  const GLsizei w = 7, h = 5;  // not square, so that swapped axes show
  TwoTargets t(w, h);
  EXPECT_EQ(t.fb.width(), w);
  EXPECT_EQ(t.fb.height(), h);
  EXPECT_EQ(t.fb.colourCount(), 2u);
  t.draw();

  std::vector<float> rgba = readTexture2DFloat(t.colour, 4);
  std::vector<std::uint32_t> id = readTexture2DUint(t.ids);
  for (GLsizei y = 0; y < h; ++y)
    for (GLsizei x = 0; x < w; ++x) {
      auto i = static_cast<std::size_t>(y * w + x);
      ASSERT_EQ(rgba[4 * i + 0], 0.25f) << x << "," << y;
      ASSERT_EQ(rgba[4 * i + 1], -1.5f) << x << "," << y;  // float target: not clamped
      ASSERT_EQ(rgba[4 * i + 2], 8.0f) << x << "," << y;
      ASSERT_EQ(id[i], 7u + static_cast<std::uint32_t>(x + 1000 * y)) << x << "," << y;
    }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// An attachment set undrawn keeps what it held through a draw (and a clear); drawn again, it
// takes the draw.
TEST_F(GpuTest, AnUndrawnAttachmentKeepsWhatItHeld) {
  const GLsizei w = 3, h = 2;
  TwoTargets t(w, h);
  t.fb.clearColour(0, glm::vec4(3.0f));
  t.fb.setColourDrawn(0, false);
  t.fb.clearColour(0, glm::vec4(9.0f));
  t.draw();
  EXPECT_EQ(readTexture2DFloat(t.colour, 4), std::vector<float>(4 * w * h, 3.0f));
  EXPECT_EQ(readTexture2DUint(t.ids)[0], 7u);  // the other attachment is drawn as before
  t.fb.setColourDrawn(0, true);
  t.draw();
  EXPECT_EQ(readTexture2DFloat(t.colour, 4)[0], 0.25f);
  EXPECT_THROW(t.fb.setColourDrawn(2, false), std::out_of_range);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GpuTest, BindSetsTheViewportAndClearsObeyTheIndex) {
  Texture2D a({4, 2, GL_RGBA8, 1, {}, {}, {}});
  Texture2D b({4, 2, GL_RGBA8, 1, {}, {}, {}});
  Framebuffer fb({{{&a, 0}, {&b, 0}}, {}, {}});
  fb.bind();
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 4);
  EXPECT_EQ(viewport[3], 2);
  fb.clearColour(0, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  fb.clearColour(1, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
  EXPECT_EQ(readTexture2DFloat(a, 4)[0], 1.0f);
  EXPECT_EQ(readTexture2DFloat(b, 4)[2], 1.0f);
  EXPECT_EQ(readTexture2DFloat(b, 4)[0], 0.0f);
  EXPECT_THROW(fb.clearColour(2, glm::vec4(0.0f)), std::out_of_range);
  EXPECT_THROW(fb.clearDepth(1.0f), std::logic_error);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GpuTest, DepthLayerOfAnArrayIsItsOwnTarget) {
  Texture2DArray cascades({8, 8, 3, GL_DEPTH_COMPONENT32F, 1, true, {}, "cascades"});
  const float one = 1.0f;
  glClearTexImage(cascades.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  DepthAttachment layer1;
  layer1.array = &cascades;
  layer1.layer = 1;
  Framebuffer fb({{}, layer1, "cascade 1"});
  EXPECT_EQ(fb.colourCount(), 0u);
  fb.clearDepth(0.375f);
  EXPECT_EQ(readTextureLayerFloat(cascades, 0), std::vector<float>(64, 1.0f));
  EXPECT_EQ(readTextureLayerFloat(cascades, 1), std::vector<float>(64, 0.375f));
  EXPECT_EQ(readTextureLayerFloat(cascades, 2), std::vector<float>(64, 1.0f));
  layer1.layer = 3;
  EXPECT_THROW(Framebuffer({{}, layer1, {}}), std::out_of_range);
}

TEST_F(GpuTest, BlitsCopyDepthAndColour) {
  Texture2D depthA({4, 4, GL_DEPTH_COMPONENT32F, 1, {}, {}, {}});
  Texture2D depthB({4, 4, GL_DEPTH_COMPONENT32F, 1, {}, {}, {}});
  Texture2D colourA({4, 4, GL_RGBA16F, 1, {}, {}, {}});
  Texture2D colourB({4, 4, GL_RGBA16F, 1, {}, {}, {}});
  Framebuffer a({{{&colourA, 0}}, {&depthA, nullptr, 0, 0}, "a"});
  Framebuffer b({{{&colourB, 0}}, {&depthB, nullptr, 0, 0}, "b"});
  a.clearDepth(0.25f);
  b.clearDepth(1.0f);
  a.clearColour(0, glm::vec4(0.5f, 2.0f, -4.0f, 1.0f));
  b.clearColour(0, glm::vec4(0.0f));
  a.blitDepthTo(b);
  EXPECT_EQ(readTexture2DFloat(depthB, 1), std::vector<float>(16, 0.25f));
  EXPECT_EQ(readTexture2DFloat(colourB, 4)[1], 0.0f);  // depth only
  a.blitColourTo(b);
  std::vector<float> colour = readTexture2DFloat(colourB, 4);
  EXPECT_EQ(colour[60], 0.5f);
  EXPECT_EQ(colour[61], 2.0f);
  EXPECT_EQ(colour[62], -4.0f);
}

TEST_F(GpuTest, IncompleteFramebufferThrowsWithItsStatus) {
  Texture2D depth({4, 4, GL_DEPTH_COMPONENT32F, 1, {}, {}, {}});
  GLint before = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &before);
  try {
    Framebuffer fb({{{&depth, 0}}, {}, "depth as colour"});  // not colour-renderable
    ADD_FAILURE() << "no error";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::FramebufferIncomplete);
    std::string message = e.what();
    EXPECT_NE(message.find("GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"), std::string::npos) << message;
    EXPECT_NE(message.find("'depth as colour'"), std::string::npos) << message;
  }
  takeDebugErrors();  // a driver may also report the attachment through KHR_debug

  Texture2D small({2, 2, GL_RGBA8, 1, {}, {}, {}});
  Texture2D large({4, 4, GL_RGBA8, 0, {}, {}, {}});
  EXPECT_THROW(Framebuffer({{{&small, 0}, {&large, 0}}, {}, {}}), std::invalid_argument);
  EXPECT_NO_THROW(Framebuffer({{{&large, 1}, {&small, 0}}, {}, {}}));  // level 1 of 4x4 is 2x2
}

TEST_F(GpuTest, FramebufferIsMoveOnlyAndFreesItsName) {
  Texture2D colour({2, 2, GL_RGBA8, 1, {}, {}, {}});
  Framebuffer a({{{&colour, 0}}, {}, {}});
  GLuint name = a.id();
  Framebuffer b(std::move(a));
  EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  EXPECT_TRUE(glIsFramebuffer(name));
  b = Framebuffer();
  EXPECT_FALSE(glIsFramebuffer(name));
  Framebuffer window = Framebuffer::window(640, 480);
  EXPECT_EQ(window.id(), 0u);
  EXPECT_EQ(window.width(), 640);
  static_assert(!std::is_copy_constructible_v<Framebuffer>);
}

}  // namespace
}  // namespace prism::gpu

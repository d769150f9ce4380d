// Vertex arrays through the driver: an indexed quad with an interleaved float position and a
// normalised byte colour covers exactly the pixels whose centres it contains.
#include "gpu/vertex_array.h"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "gpu/framebuffer.h"
#include "gpu/gpu_test_support.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

struct Vertex {
  float x, y;
  std::uint8_t rgba[4];
};
static_assert(sizeof(Vertex) == 12);

TEST_F(GpuTest, IndexedQuadCoversItsPixelsWithItsColour) {
  // [-0.5, 0.5]² in clip space on a 16×16 target: pixel centres (i + 0.5)/8 - 1 lie inside
  // for i = 4..11, and none lies on an edge, so coverage is exact under any fill convention.
  const std::array<Vertex, 4> vertices{{{-0.5f, -0.5f, {255, 0, 51, 255}},
                                        {0.5f, -0.5f, {255, 0, 51, 255}},
                                        {0.5f, 0.5f, {255, 0, 51, 255}},
                                        {-0.5f, 0.5f, {255, 0, 51, 255}}}};
  const std::array<GLuint, 6> indices{0, 1, 2, 0, 2, 3};
  Buffer vertexBuffer = Buffer::fromSpan(std::span<const Vertex>(vertices), "quad vertices");
  Buffer indexBuffer = Buffer::fromSpan(std::span<const GLuint>(indices), "quad indices");
  VertexArray quad({{{0, 2, GL_FLOAT, false, false, offsetof(Vertex, x)},
                     {1, 4, GL_UNSIGNED_BYTE, true, false, offsetof(Vertex, rgba)}},
                    &vertexBuffer,
                    sizeof(Vertex),
                    &indexBuffer,
                    GL_TRIANGLES,
                    "quad"});
  EXPECT_TRUE(quad.indexed());
  EXPECT_EQ(quad.elementCount(), 6);

  Texture2D target({16, 16, GL_RGBA32F, 1, {}, {}, "target"});
  Framebuffer fb({{{&target, 0}}, {}, {}});
  fb.bind();
  fb.clearColour(0, glm::vec4(0.0f));
  Program program = testing::drawProgram("vertex_colour.vert", "vertex_colour.frag");
  program.use();
  quad.draw();

  std::vector<float> rgba = readTexture2DFloat(target, 4);
  int covered = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      auto i = static_cast<std::size_t>(y * 16 + x) * 4;
      bool inside = x >= 4 && x <= 11 && y >= 4 && y <= 11;
      covered += rgba[i + 3] > 0.0f;
      if (inside) {
        ASSERT_EQ(rgba[i], 1.0f) << x << "," << y;
        ASSERT_NEAR(rgba[i + 2], 0.2f, 1e-6) << x << "," << y;  // 51/255, normalised
      } else {
        ASSERT_EQ(rgba[i + 3], 0.0f) << x << "," << y;
      }
    }
  EXPECT_EQ(covered, 64);

  // Half the indices: only the lower-right triangle (below the diagonal x = y).
  fb.clearColour(0, glm::vec4(0.0f));
  quad.draw(3);
  rgba = readTexture2DFloat(target, 4);
  EXPECT_GT(rgba[(5 * 16 + 10) * 4 + 3], 0.0f);
  EXPECT_EQ(rgba[(10 * 16 + 5) * 4 + 3], 0.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
}

TEST_F(GpuTest, VertexArrayChecksItsDescAndDrawRanges) {
  std::array<float, 6> positions{};
  Buffer buffer = Buffer::fromSpan(std::span<const float>(positions));
  EXPECT_THROW(
      VertexArray({{{0, 2, GL_FLOAT, false, false, 0}}, nullptr, 8, nullptr, GL_TRIANGLES, {}}),
      std::invalid_argument);
  EXPECT_THROW(
      VertexArray({{{0, 5, GL_FLOAT, false, false, 0}}, &buffer, 8, nullptr, GL_TRIANGLES, {}}),
      std::invalid_argument);
  EXPECT_THROW(
      VertexArray({{{0, 2, GL_FLOAT, false, false, 8}}, &buffer, 8, nullptr, GL_TRIANGLES, {}}),
      std::invalid_argument);
  VertexArray triangle(
      {{{0, 2, GL_FLOAT, false, false, 0}}, &buffer, 8, nullptr, GL_TRIANGLES, {}});
  EXPECT_FALSE(triangle.indexed());
  EXPECT_EQ(triangle.elementCount(), 3);
  EXPECT_THROW(triangle.draw(3, 1), std::out_of_range);
  VertexArray empty = VertexArray::attributeless();
  EXPECT_NE(empty.id(), 0u);
  EXPECT_THROW(empty.draw(), std::out_of_range);
  VertexArray moved(std::move(empty));
  EXPECT_EQ(empty.id(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  EXPECT_TRUE(glIsVertexArray(moved.id()));
}

}  // namespace
}  // namespace prism::gpu

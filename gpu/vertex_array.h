// A vertex array object over direct state access: attribute formats read from one interleaved
// vertex Buffer (binding 0) and an optional index Buffer of GL_UNSIGNED_INT, so that a mesh
// draws with one bind and one call. VertexArray::attributeless() is the empty VAO a core
// context still requires for draws whose vertex shader makes positions from gl_VertexID (the
// full-screen triangle of every post-process pass). The buffers are referenced by name, not
// owned: they must outlive the VAO. Move-only.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "gpu/buffer.h"

namespace prism::gpu {

struct VertexAttribute {
  GLuint location = 0;      // layout(location = N) in the vertex shader
  GLint components = 0;     // 1..4
  GLenum type = GL_FLOAT;   // of each component in the buffer
  bool normalized = false;  // integer types: map to [0, 1] or [-1, 1]
  bool integer = false;     // an ivec/uvec input, read without conversion (AttribIFormat)
  GLuint offsetBytes = 0;   // from the start of the vertex
};

struct VertexArrayDesc {
  std::vector<VertexAttribute> attributes;
  const Buffer* vertices = nullptr;  // interleaved, `strideBytes` per vertex
  GLsizei strideBytes = 0;
  const Buffer* indices = nullptr;  // optional: GL_UNSIGNED_INT indices
  GLenum primitive = GL_TRIANGLES;
  std::string label;
};

class VertexArray {
 public:
  VertexArray() = default;  // no GL object
  explicit VertexArray(const VertexArrayDesc& desc);
  ~VertexArray();
  VertexArray(VertexArray&& other) noexcept;
  VertexArray& operator=(VertexArray&& other) noexcept;
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;

  // A VAO with no attributes and no buffers; draw(3) after a vertex shader that places a
  // full-screen triangle from gl_VertexID.
  static VertexArray attributeless(std::string label = {}, GLenum primitive = GL_TRIANGLES);

  GLuint id() const { return mId; }
  bool indexed() const { return mIndexed; }
  // Vertices a draw() with no count uses: the index count, else the vertex count, else 0.
  GLsizei elementCount() const { return mCount; }

  void bind() const { glBindVertexArray(mId); }
  // Binds the VAO and draws `count` indices (glDrawElements) or vertices (glDrawArrays) from
  // `first`, with the program in use and the framebuffer bound. A count of 0 draws them all;
  // an attributeless VAO needs an explicit count.
  void draw(GLsizei count = 0, GLint first = 0) const;

 private:
  void release();

  GLuint mId = 0;
  GLenum mPrimitive = GL_TRIANGLES;
  GLsizei mCount = 0;
  bool mIndexed = false;
};

}  // namespace prism::gpu

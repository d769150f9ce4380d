#include "gpu/vertex_array.h"

#include <cstdint>
#include <stdexcept>
#include <utility>

#include "gpu/object_counter.h"

namespace prism::gpu {
namespace {

GLuint createVertexArray(const std::string& label) {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  countGlObjects(GlObjectKind::VertexArray, 1);
  if (!label.empty())
    glObjectLabel(GL_VERTEX_ARRAY, id, static_cast<GLsizei>(label.size()), label.data());
  return id;
}

void checkDesc(const VertexArrayDesc& desc) {
  if (!desc.attributes.empty() && !desc.vertices)
    throw std::invalid_argument("VertexArray: attributes without a vertex buffer");
  if (desc.vertices && desc.strideBytes <= 0)
    throw std::invalid_argument("VertexArray: a vertex buffer needs a positive stride");
  for (const VertexAttribute& a : desc.attributes) {
    if (a.components < 1 || a.components > 4)
      throw std::invalid_argument("VertexArray: attribute " + std::to_string(a.location) + " has " +
                                  std::to_string(a.components) + " components");
    if (a.offsetBytes >= static_cast<GLuint>(desc.strideBytes))
      throw std::invalid_argument("VertexArray: attribute " + std::to_string(a.location) +
                                  " starts outside the vertex");
  }
  if (desc.indices && desc.indices->sizeBytes() % sizeof(GLuint) != 0)
    throw std::invalid_argument("VertexArray: the index buffer is not whole GL_UNSIGNED_INTs");
}

}  // namespace

VertexArray::VertexArray(const VertexArrayDesc& desc) : mPrimitive(desc.primitive) {
  checkDesc(desc);
  mId = createVertexArray(desc.label);
  if (desc.vertices) {
    glVertexArrayVertexBuffer(mId, 0, desc.vertices->id(), 0, desc.strideBytes);
    mCount = static_cast<GLsizei>(desc.vertices->sizeBytes() /
                                  static_cast<std::size_t>(desc.strideBytes));
  }
  for (const VertexAttribute& a : desc.attributes) {
    glEnableVertexArrayAttrib(mId, a.location);
    if (a.integer)
      glVertexArrayAttribIFormat(mId, a.location, a.components, a.type, a.offsetBytes);
    else
      glVertexArrayAttribFormat(mId, a.location, a.components, a.type,
                                a.normalized ? GL_TRUE : GL_FALSE, a.offsetBytes);
    glVertexArrayAttribBinding(mId, a.location, 0);
  }
  if (desc.indices) {
    glVertexArrayElementBuffer(mId, desc.indices->id());
    mCount = static_cast<GLsizei>(desc.indices->sizeBytes() / sizeof(GLuint));
    mIndexed = true;
  }
}

VertexArray VertexArray::attributeless(std::string label, GLenum primitive) {
  VertexArray vao;
  vao.mId = createVertexArray(label);
  vao.mPrimitive = primitive;
  return vao;
}

VertexArray::~VertexArray() { release(); }

void VertexArray::release() {
  if (!mId) return;
  glDeleteVertexArrays(1, &mId);
  countGlObjects(GlObjectKind::VertexArray, -1);
  mId = 0;
}

VertexArray::VertexArray(VertexArray&& other) noexcept
    : mId(std::exchange(other.mId, 0)),
      mPrimitive(other.mPrimitive),
      mCount(std::exchange(other.mCount, 0)),
      mIndexed(std::exchange(other.mIndexed, false)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mPrimitive = other.mPrimitive;
    mCount = std::exchange(other.mCount, 0);
    mIndexed = std::exchange(other.mIndexed, false);
  }
  return *this;
}

void VertexArray::draw(GLsizei count, GLint first) const {
  if (count == 0) count = mCount - first;
  if (count <= 0 || first < 0 || (mCount > 0 && first + count > mCount))
    throw std::out_of_range("VertexArray::draw: " + std::to_string(count) + " from " +
                            std::to_string(first) + " of " + std::to_string(mCount) +
                            " (an attributeless VAO needs a count)");
  bind();
  if (mIndexed)
    glDrawElements(mPrimitive, count, GL_UNSIGNED_INT,  // offset into the element buffer
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 4u));
  else
    glDrawArrays(mPrimitive, first, count);
}

}  // namespace prism::gpu

#include "gpu/buffer.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "gpu/object_counter.h"
#include "gpu/storage.h"

namespace prism::gpu {

Buffer::Buffer(const BufferDesc& desc) : mSizeBytes(desc.sizeBytes) {
  if (desc.sizeBytes == 0) throw std::invalid_argument("prism::gpu::Buffer: size 0");
  glCreateBuffers(1, &mId);
  countGlObjects(GlObjectKind::Buffer, 1);
  try {
    makeStorage(Diagnostic::BufferStorageFailed,
                "prism::gpu::Buffer" + (desc.label.empty() ? "" : " '" + desc.label + "'") + " of " +
                    std::to_string(desc.sizeBytes) + " bytes",
                [&] { glNamedBufferStorage(mId, static_cast<GLsizeiptr>(desc.sizeBytes), desc.data, desc.storageFlags); });
  } catch (...) {
    release();  // no destructor runs for a constructor that throws
    throw;
  }
  if (!desc.label.empty())
    glObjectLabel(GL_BUFFER, mId, static_cast<GLsizei>(desc.label.size()), desc.label.data());
  if (!desc.data) {
    // Immutable storage starts undefined; zero it so that a kernel that skips an element
    // leaves a known value for tests to see.
    const GLubyte zero = 0;
    glClearNamedBufferData(mId, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &zero);
  }
}

Buffer::~Buffer() { release(); }

void Buffer::release() {
  if (!mId) return;
  glDeleteBuffers(1, &mId);
  countGlObjects(GlObjectKind::Buffer, -1);
  mId = 0;
}

Buffer::Buffer(Buffer&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mSizeBytes(std::exchange(other.mSizeBytes, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mSizeBytes = std::exchange(other.mSizeBytes, 0);
  }
  return *this;
}

void Buffer::checkRange(std::size_t offsetBytes, std::size_t sizeBytes) const {
  if (offsetBytes > mSizeBytes || sizeBytes > mSizeBytes - offsetBytes)
    throw std::out_of_range("prism::gpu::Buffer: bytes [" + std::to_string(offsetBytes) + ", " +
                            std::to_string(offsetBytes + sizeBytes) + ") outside a buffer of " +
                            std::to_string(mSizeBytes));
}

std::size_t Buffer::elementCount(std::size_t elementBytes) const {
  if (mSizeBytes % elementBytes != 0)
    throw std::invalid_argument("prism::gpu::Buffer: " + std::to_string(mSizeBytes) +
                                " bytes is not a whole number of " + std::to_string(elementBytes) +
                                "-byte elements");
  return mSizeBytes / elementBytes;
}

void Buffer::upload(std::size_t offsetBytes, std::span<const std::byte> bytes) {
  checkRange(offsetBytes, bytes.size());
  if (bytes.empty()) return;
  glNamedBufferSubData(mId, static_cast<GLintptr>(offsetBytes),
                       static_cast<GLsizeiptr>(bytes.size()), bytes.data());
}

void Buffer::download(std::size_t offsetBytes, std::span<std::byte> bytes) const {
  checkRange(offsetBytes, bytes.size());
  if (bytes.empty()) return;
  glGetNamedBufferSubData(mId, static_cast<GLintptr>(offsetBytes),
                          static_cast<GLsizeiptr>(bytes.size()), bytes.data());
}

void Buffer::bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, mId); }

}  // namespace prism::gpu

// A GPU buffer with immutable storage, over direct state access (OpenGL 4.5): created with
// glCreateBuffers + glNamedBufferStorage, updated with glNamedBufferSubData, read back with
// glGetNamedBufferSubData. Move-only; the name is deleted with the object (a context must be
// current). Offsets and sizes are in bytes and checked: a range outside the buffer throws
// std::out_of_range (a programmer error, never a GL error).
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace prism::gpu {

struct BufferDesc {
  std::size_t sizeBytes = 0;
  const void* data = nullptr;                        // initial contents, or zero-filled
  GLbitfield storageFlags = GL_DYNAMIC_STORAGE_BIT;  // allows upload(); add map bits as needed
  std::string label;                                 // glObjectLabel, shown in debug messages
};

class Buffer {
 public:
  Buffer() = default;  // no GL object
  explicit Buffer(const BufferDesc& desc);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // A buffer holding a copy of `values` (trivially copyable elements, std430 layout is the
  // caller's business: use vec4-sized elements for vec3 data).
  template <class T>
  static Buffer fromSpan(std::span<const T> values, std::string label = {},
                         GLbitfield storageFlags = GL_DYNAMIC_STORAGE_BIT) {
    return Buffer({values.size_bytes(), values.data(), storageFlags, std::move(label)});
  }

  GLuint id() const { return mId; }
  std::size_t sizeBytes() const { return mSizeBytes; }

  void upload(std::size_t offsetBytes, std::span<const std::byte> bytes);
  void download(std::size_t offsetBytes, std::span<std::byte> bytes) const;

  // The whole buffer as elements of T (its size must be a multiple of sizeof(T)).
  template <class T>
  std::vector<T> read() const {
    std::vector<T> values(elementCount(sizeof(T)));
    download(0, std::as_writable_bytes(std::span<T>(values)));
    return values;
  }

  // glBindBufferBase, e.g. (GL_SHADER_STORAGE_BUFFER, binding) for an SSBO.
  void bindBase(GLenum target, GLuint index) const;

 private:
  void release();  // deletes the name, if any
  void checkRange(std::size_t offsetBytes, std::size_t sizeBytes) const;
  std::size_t elementCount(std::size_t elementBytes) const;

  GLuint mId = 0;
  std::size_t mSizeBytes = 0;
};

}  // namespace prism::gpu

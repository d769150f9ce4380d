#include "gpu/texture.h"

#include <stdexcept>
#include <utility>

namespace prism::gpu {

namespace {

std::size_t channels(GLenum format) {
  switch (format) {
    case GL_RED: return 1;
    case GL_RG: return 2;
    case GL_RGB: return 3;
    case GL_RGBA: return 4;
    default: throw std::invalid_argument("Texture3D: unsupported texel format");
  }
}

}  // namespace

Texture3D::Texture3D(const Texture3DDesc& desc) {
  if (desc.width <= 0 || desc.height <= 0 || desc.depth <= 0)
    throw std::invalid_argument("Texture3D: dimensions must be positive");
  std::size_t expected = static_cast<std::size_t>(desc.width) * static_cast<std::size_t>(desc.height) *
                         static_cast<std::size_t>(desc.depth) * channels(desc.format);
  if (desc.texels.size() != expected)
    throw std::invalid_argument("Texture3D: texel count does not match the size");
  glCreateTextures(GL_TEXTURE_3D, 1, &mId);
  glTextureStorage3D(mId, 1, desc.internalFormat, desc.width, desc.height, desc.depth);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // texels come from client memory
  glTextureSubImage3D(mId, 0, 0, 0, 0, desc.width, desc.height, desc.depth, desc.format, GL_FLOAT,
                      desc.texels.data());
  glTextureParameteri(mId, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(mId, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(mId, wrap, GL_CLAMP_TO_EDGE);
  if (!desc.label.empty())
    glObjectLabel(GL_TEXTURE, mId, static_cast<GLsizei>(desc.label.size()), desc.label.data());
}

Texture3D::~Texture3D() {
  if (mId) glDeleteTextures(1, &mId);
}

Texture3D::Texture3D(Texture3D&& other) noexcept : mId(std::exchange(other.mId, 0)) {}

Texture3D& Texture3D::operator=(Texture3D&& other) noexcept {
  if (this != &other) {
    if (mId) glDeleteTextures(1, &mId);
    mId = std::exchange(other.mId, 0);
  }
  return *this;
}

}  // namespace prism::gpu

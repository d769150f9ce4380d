#include "gpu/texture.h"

#include <algorithm>
#include <bit>
#include <functional>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "gpu/error.h"
#include "gpu/object_counter.h"
#include "gpu/storage.h"

namespace prism::gpu {

namespace {

void makeTextureStorage(const char* kind, const std::string& label, std::size_t texels,
                        const std::function<void()>& storage) {
  makeStorage(Diagnostic::TextureStorageFailed,
              std::string("prism::gpu::") + kind + (label.empty() ? "" : " '" + label + "'") + " of " +
                  std::to_string(texels) + " texels",
              storage);
}

std::size_t channels(GLenum format) {
  switch (format) {
    case GL_RED:
    case GL_RED_INTEGER:
    case GL_DEPTH_COMPONENT: return 1;
    case GL_RG:
    case GL_RG_INTEGER: return 2;
    case GL_RGB:
    case GL_RGB_INTEGER: return 3;
    case GL_RGBA:
    case GL_RGBA_INTEGER: return 4;
    default: throw std::invalid_argument("prism::gpu texture: unsupported texel format");
  }
}

std::size_t componentBytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_HALF_FLOAT: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: return 4;
    default: throw std::invalid_argument("prism::gpu texture: unsupported component type");
  }
}

bool isUnsignedIntegerFormat(GLenum f) {
  switch (f) {
    case GL_R8UI:
    case GL_R16UI:
    case GL_R32UI:
    case GL_RG8UI:
    case GL_RG16UI:
    case GL_RG32UI:
    case GL_RGB8UI:
    case GL_RGB16UI:
    case GL_RGB32UI:
    case GL_RGBA8UI:
    case GL_RGBA16UI:
    case GL_RGBA32UI:
    case GL_RGB10_A2UI: return true;
    default: return false;
  }
}

bool isIntegerFormat(GLenum f) {
  switch (f) {
    case GL_R8I:
    case GL_R16I:
    case GL_R32I:
    case GL_RG8I:
    case GL_RG16I:
    case GL_RG32I:
    case GL_RGB8I:
    case GL_RGB16I:
    case GL_RGB32I:
    case GL_RGBA8I:
    case GL_RGBA16I:
    case GL_RGBA32I: return true;
    default: return isUnsignedIntegerFormat(f);
  }
}

GLsizei mipExtent(GLsizei size, GLint level) { return std::max<GLsizei>(1, size >> level); }

// Resolves levels = 0 to the full chain and rejects sizes GL would reject less clearly.
GLsizei checkedLevels(const char* what, GLsizei width, GLsizei height, GLsizei levels) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument(std::string(what) + ": dimensions must be positive");
  auto chain = static_cast<GLsizei>(
      std::bit_width(static_cast<unsigned>(std::max(width, height))));  // 1 + floor(log2)
  if (levels == 0) return chain;
  if (levels < 0 || levels > chain)
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(levels) +
                                " mip levels (1.." + std::to_string(chain) + " allowed)");
  return levels;
}

void applySampling(GLuint id, const SamplingDesc& s, GLenum internalFormat, GLsizei levels) {
  bool integer = isIntegerFormat(internalFormat);
  GLenum minFilter = s.minFilter;
  if (!minFilter)
    minFilter = integer ? (levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST)
                        : (levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  GLenum magFilter = s.magFilter ? s.magFilter : integer ? GL_NEAREST : GL_LINEAR;
  GLenum wrap = s.wrap ? s.wrap : GL_CLAMP_TO_EDGE;
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
}

void setLabel(GLuint id, const std::string& text) {
  if (!text.empty()) glObjectLabel(GL_TEXTURE, id, static_cast<GLsizei>(text.size()), text.data());
}

// Sets a pixel-store alignment for one transfer and restores the caller's: our rows are tight.
class TightRows {
 public:
  explicit TightRows(GLenum alignment) : mAlignment(alignment) {
    glGetIntegerv(alignment, &mPrevious);
    glPixelStorei(alignment, 1);
  }
  ~TightRows() { glPixelStorei(mAlignment, mPrevious); }
  TightRows(const TightRows&) = delete;
  TightRows& operator=(const TightRows&) = delete;

 private:
  GLenum mAlignment;
  GLint mPrevious = 4;
};

GLenum readFormat(GLenum internalFormat, int channelCount, bool integer) {
  if (channelCount < 1 || channelCount > 4)
    throw std::invalid_argument("prism::gpu texture read-back: 1 to 4 channels");
  if (isDepthFormat(internalFormat)) {
    if (channelCount != 1 || integer)
      throw std::invalid_argument("prism::gpu texture read-back: depth reads as 1 float");
    return GL_DEPTH_COMPONENT;
  }
  if (integer != isIntegerFormat(internalFormat))
    throw std::invalid_argument(integer ? "prism::gpu texture read-back: not an integer format"
                                        : "prism::gpu texture read-back: an integer format");
  static constexpr GLenum kFloat[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  static constexpr GLenum kInteger[] = {GL_RED_INTEGER, GL_RG_INTEGER, GL_RGB_INTEGER,
                                        GL_RGBA_INTEGER};
  return (integer ? kInteger : kFloat)[channelCount - 1];
}

void checkLevel(GLint level, GLsizei levels) {
  if (level < 0 || level >= levels)
    throw std::out_of_range("prism::gpu texture: level " + std::to_string(level) + " of " +
                            std::to_string(levels));
}

template <class T>
std::vector<T> readLevel(const Texture2D& texture, int channelCount, GLint level, GLenum type) {
  GLenum format =
      readFormat(texture.internalFormat(), channelCount, std::is_same_v<T, std::uint32_t>);
  checkLevel(level, texture.levels());
  std::vector<T> texels(static_cast<std::size_t>(texture.width(level)) *
                        static_cast<std::size_t>(texture.height(level)) *
                        static_cast<std::size_t>(channelCount));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);  // into client memory
  TightRows tight(GL_PACK_ALIGNMENT);
  glGetTextureImage(texture.id(), level, format, type,
                    static_cast<GLsizei>(texels.size() * sizeof(T)), texels.data());
  return texels;
}

}  // namespace

bool isDepthFormat(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8: return true;
    default: return false;
  }
}

std::size_t texelBytes(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_R8:
    case GL_R8I:
    case GL_R8UI: return 1;
    case GL_R16F:
    case GL_R16I:
    case GL_R16UI:
    case GL_RG8:
    case GL_RG8I:
    case GL_RG8UI:
    case GL_DEPTH_COMPONENT16: return 2;
    case GL_RGB8:
    case GL_SRGB8:
    case GL_RGB8I:
    case GL_RGB8UI:
    case GL_DEPTH_COMPONENT24: return 3;
    case GL_R32F:
    case GL_R32I:
    case GL_R32UI:
    case GL_RG16F:
    case GL_RG16I:
    case GL_RG16UI:
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_RGBA8I:
    case GL_RGBA8UI:
    case GL_RGB10_A2:
    case GL_RGB10_A2UI:
    case GL_R11F_G11F_B10F:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8: return 4;
    case GL_RGB16F:
    case GL_RGB16I:
    case GL_RGB16UI: return 6;
    case GL_RG32F:
    case GL_RG32I:
    case GL_RG32UI:
    case GL_RGBA16F:
    case GL_RGBA16I:
    case GL_RGBA16UI:
    case GL_DEPTH32F_STENCIL8: return 8;
    case GL_RGB32F:
    case GL_RGB32I:
    case GL_RGB32UI: return 12;
    case GL_RGBA32F:
    case GL_RGBA32I:
    case GL_RGBA32UI: return 16;
    default: throw std::invalid_argument("prism::gpu texelBytes: unsupported internal format");
  }
}

// ---- Texture3D ----

Texture3D::Texture3D(const Texture3DDesc& desc) {
  if (desc.width <= 0 || desc.height <= 0 || desc.depth <= 0)
    throw std::invalid_argument("Texture3D: dimensions must be positive");
  std::size_t expected = static_cast<std::size_t>(desc.width) *
                         static_cast<std::size_t>(desc.height) *
                         static_cast<std::size_t>(desc.depth) * channels(desc.format);
  if (desc.texels.size() != expected)
    throw std::invalid_argument("Texture3D: texel count does not match the size");
  glCreateTextures(GL_TEXTURE_3D, 1, &mId);
  countGlObjects(GlObjectKind::Texture, 1);
  try {
    makeTextureStorage("Texture3D", desc.label, expected / channels(desc.format),
                [&] { glTextureStorage3D(mId, 1, desc.internalFormat, desc.width, desc.height, desc.depth); });
  } catch (...) {
    release();  // no destructor runs for a constructor that throws
    throw;
  }
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // texels come from client memory
  glTextureSubImage3D(mId, 0, 0, 0, 0, desc.width, desc.height, desc.depth, desc.format, GL_FLOAT,
                      desc.texels.data());
  glTextureParameteri(mId, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(mId, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(mId, wrap, GL_CLAMP_TO_EDGE);
  setLabel(mId, desc.label);
  mSizeBytes = expected / channels(desc.format) * texelBytes(desc.internalFormat);
}

Texture3D::~Texture3D() { release(); }

void Texture3D::release() {
  if (!mId) return;
  glDeleteTextures(1, &mId);
  countGlObjects(GlObjectKind::Texture, -1);
  mId = 0;
}

Texture3D::Texture3D(Texture3D&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mSizeBytes(std::exchange(other.mSizeBytes, 0)) {}

Texture3D& Texture3D::operator=(Texture3D&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mSizeBytes = std::exchange(other.mSizeBytes, 0);
  }
  return *this;
}

// ---- Texture2D ----

Texture2D::Texture2D(const Texture2DDesc& desc)
    : mWidth(desc.width),
      mHeight(desc.height),
      mLevels(checkedLevels("Texture2D", desc.width, desc.height, desc.levels)),
      mInternalFormat(desc.internalFormat) {
  glCreateTextures(GL_TEXTURE_2D, 1, &mId);
  countGlObjects(GlObjectKind::Texture, 1);
  try {
    makeTextureStorage("Texture2D", desc.label, static_cast<std::size_t>(mWidth) * static_cast<std::size_t>(mHeight),
                [&] { glTextureStorage2D(mId, mLevels, mInternalFormat, mWidth, mHeight); });
    applySampling(mId, desc.sampling, mInternalFormat, mLevels);
    setLabel(mId, desc.label);
    if (!desc.data.bytes.empty()) upload(desc.data, 0);
  } catch (...) {
    release();  // no destructor runs for a constructor that throws
    throw;
  }
}

Texture2D::~Texture2D() { release(); }

void Texture2D::release() {
  if (!mId) return;
  glDeleteTextures(1, &mId);
  countGlObjects(GlObjectKind::Texture, -1);
  mId = 0;
}

Texture2D::Texture2D(Texture2D&& other) noexcept
    : mId(std::exchange(other.mId, 0)),
      mWidth(std::exchange(other.mWidth, 0)),
      mHeight(std::exchange(other.mHeight, 0)),
      mLevels(std::exchange(other.mLevels, 0)),
      mInternalFormat(std::exchange(other.mInternalFormat, 0)) {}

Texture2D& Texture2D::operator=(Texture2D&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mWidth = std::exchange(other.mWidth, 0);
    mHeight = std::exchange(other.mHeight, 0);
    mLevels = std::exchange(other.mLevels, 0);
    mInternalFormat = std::exchange(other.mInternalFormat, 0);
  }
  return *this;
}

GLsizei Texture2D::width(GLint level) const { return mipExtent(mWidth, level); }
GLsizei Texture2D::height(GLint level) const { return mipExtent(mHeight, level); }

std::size_t Texture2D::sizeBytes() const {
  if (!mId) return 0;
  std::size_t texels = 0;
  for (GLint level = 0; level < mLevels; ++level)
    texels += static_cast<std::size_t>(width(level)) * static_cast<std::size_t>(height(level));
  return texels * texelBytes(mInternalFormat);
}

void Texture2D::upload(const TextureData& data, GLint level) {
  checkLevel(level, mLevels);
  std::size_t expected = static_cast<std::size_t>(width(level)) *
                         static_cast<std::size_t>(height(level)) * channels(data.format) *
                         componentBytes(data.type);
  if (data.bytes.size() != expected)
    throw std::invalid_argument("Texture2D: " + std::to_string(data.bytes.size()) +
                                " bytes for a level of " + std::to_string(expected));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  TightRows tight(GL_UNPACK_ALIGNMENT);
  glTextureSubImage2D(mId, level, 0, 0, width(level), height(level), data.format, data.type,
                      data.bytes.data());
}

void Texture2D::generateMipmaps() { glGenerateTextureMipmap(mId); }

void Texture2D::bindImage(GLuint unit, GLenum access, GLint level) const {
  glBindImageTexture(unit, mId, level, GL_FALSE, 0, access, mInternalFormat);
}

// ---- Texture2DArray ----

void Texture2DArray::bindImage(GLuint unit, GLenum access, GLint level) const {
  glBindImageTexture(unit, mId, level, GL_TRUE, 0, access, mInternalFormat);
}

void Texture2DArray::upload(const TextureData& data, GLint level) {
  checkLevel(level, mLevels);
  std::size_t expected = static_cast<std::size_t>(width(level)) * static_cast<std::size_t>(height(level)) *
                         static_cast<std::size_t>(mLayers) * channels(data.format) * componentBytes(data.type);
  if (data.bytes.size() != expected)
    throw std::invalid_argument("Texture2DArray: " + std::to_string(data.bytes.size()) + " bytes for a level of " +
                                std::to_string(expected));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  TightRows tight(GL_UNPACK_ALIGNMENT);
  glTextureSubImage3D(mId, level, 0, 0, 0, width(level), height(level), mLayers, data.format, data.type,
                      data.bytes.data());
}

void Texture2DArray::generateMipmaps() { glGenerateTextureMipmap(mId); }

Texture2DArray::Texture2DArray(const Texture2DArrayDesc& desc)
    : mWidth(desc.width),
      mHeight(desc.height),
      mLayers(desc.layers),
      mLevels(checkedLevels("Texture2DArray", desc.width, desc.height, desc.levels)),
      mInternalFormat(desc.internalFormat) {
  if (desc.layers <= 0) throw std::invalid_argument("Texture2DArray: layers must be positive");
  if (desc.compareRefToTexture && !isDepthFormat(desc.internalFormat))
    throw std::invalid_argument("Texture2DArray: compare mode needs a depth format");
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &mId);
  countGlObjects(GlObjectKind::Texture, 1);
  try {
    makeTextureStorage("Texture2DArray", desc.label,
                static_cast<std::size_t>(mWidth) * static_cast<std::size_t>(mHeight) * static_cast<std::size_t>(mLayers),
                [&] { glTextureStorage3D(mId, mLevels, mInternalFormat, mWidth, mHeight, mLayers); });
  } catch (...) {
    release();  // no destructor runs for a constructor that throws
    throw;
  }
  applySampling(mId, desc.sampling, mInternalFormat, mLevels);
  if (desc.compareRefToTexture) {
    glTextureParameteri(mId, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(mId, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  setLabel(mId, desc.label);
}

Texture2DArray::~Texture2DArray() { release(); }

void Texture2DArray::release() {
  if (!mId) return;
  glDeleteTextures(1, &mId);
  countGlObjects(GlObjectKind::Texture, -1);
  mId = 0;
}

Texture2DArray::Texture2DArray(Texture2DArray&& other) noexcept
    : mId(std::exchange(other.mId, 0)),
      mWidth(std::exchange(other.mWidth, 0)),
      mHeight(std::exchange(other.mHeight, 0)),
      mLayers(std::exchange(other.mLayers, 0)),
      mLevels(std::exchange(other.mLevels, 0)),
      mInternalFormat(std::exchange(other.mInternalFormat, 0)) {}

Texture2DArray& Texture2DArray::operator=(Texture2DArray&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mWidth = std::exchange(other.mWidth, 0);
    mHeight = std::exchange(other.mHeight, 0);
    mLayers = std::exchange(other.mLayers, 0);
    mLevels = std::exchange(other.mLevels, 0);
    mInternalFormat = std::exchange(other.mInternalFormat, 0);
  }
  return *this;
}

GLsizei Texture2DArray::width(GLint level) const { return mipExtent(mWidth, level); }
GLsizei Texture2DArray::height(GLint level) const { return mipExtent(mHeight, level); }

std::size_t Texture2DArray::sizeBytes() const {
  if (!mId) return 0;
  std::size_t texels = 0;
  for (GLint level = 0; level < mLevels; ++level)
    texels += static_cast<std::size_t>(width(level)) * static_cast<std::size_t>(height(level));
  return texels * static_cast<std::size_t>(mLayers) * texelBytes(mInternalFormat);
}

// ---- read-back ----

std::vector<float> readTexture2DFloat(const Texture2D& texture, int channels, GLint level) {
  return readLevel<float>(texture, channels, level, GL_FLOAT);
}

std::vector<std::uint32_t> readTexture2DUint(const Texture2D& texture, int channels, GLint level) {
  return readLevel<std::uint32_t>(texture, channels, level, GL_UNSIGNED_INT);
}

std::vector<float> readTextureLayerFloat(const Texture2DArray& texture, GLint layer, int channels,
                                         GLint level) {
  GLenum format = readFormat(texture.internalFormat(), channels, false);
  checkLevel(level, texture.levels());
  if (layer < 0 || layer >= texture.layers())
    throw std::out_of_range("readTextureLayerFloat: layer " + std::to_string(layer) + " of " +
                            std::to_string(texture.layers()));
  GLsizei w = texture.width(level), h = texture.height(level);
  std::vector<float> texels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                            static_cast<std::size_t>(channels));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  TightRows tight(GL_PACK_ALIGNMENT);
  glGetTextureSubImage(texture.id(), level, 0, 0, layer, w, h, 1, format, GL_FLOAT,
                       static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  return texels;
}

}  // namespace prism::gpu

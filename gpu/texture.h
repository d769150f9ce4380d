// Textures with immutable storage over direct state access, in the three shapes the renderer
// uses: Texture3D for precomputed tables (upsampling coefficients, later the atmosphere's
// volumes), Texture2D for render targets and images, Texture2DArray for cascaded shadow maps
// (a depth layer per cascade, optionally sampled through a sampler2DArrayShadow). Move-only;
// the name is deleted with the object (a context must be current).
//
// Read-back helpers return tightly packed rows, bottom row first (GL's order), for tests and
// for the image tools. They stall the pipeline: never call them in a frame loop.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace prism::gpu {

struct Texture3DDesc {
  GLsizei width = 1, height = 1, depth = 1;
  GLenum internalFormat = GL_RGB32F;
  GLenum format = GL_RGB;         // of `texels`
  std::span<const float> texels;  // width·height·depth·channels floats, x fastest
  std::string label;
};

class Texture3D {
 public:
  Texture3D() = default;
  explicit Texture3D(const Texture3DDesc& desc);
  ~Texture3D();
  Texture3D(Texture3D&& other) noexcept;
  Texture3D& operator=(Texture3D&& other) noexcept;
  Texture3D(const Texture3D&) = delete;
  Texture3D& operator=(const Texture3D&) = delete;

  GLuint id() const { return mId; }
  void bind(GLuint unit) const { glBindTextureUnit(unit, mId); }
  std::size_t sizeBytes() const { return mSizeBytes; }  // of its storage (texelBytes); 0 without a GL object

 private:
  void release();

  GLuint mId = 0;
  std::size_t mSizeBytes = 0;
};

// Client-memory texels for one level: tightly packed rows (no 4-byte row alignment), bottom
// row first. `format` and `type` are glTextureSubImage's, e.g. GL_RGBA + GL_FLOAT, or
// GL_RED_INTEGER + GL_UNSIGNED_INT for GL_R32UI. Empty bytes: nothing to upload.
struct TextureData {
  GLenum format = GL_RGBA;
  GLenum type = GL_UNSIGNED_BYTE;
  std::span<const std::byte> bytes;
};

// Sampling state; zero means: GL_NEAREST for integer formats (linear filtering makes them
// incomplete), else GL_LINEAR, with GL_LINEAR_MIPMAP_LINEAR minification when there are mip
// levels; GL_CLAMP_TO_EDGE on every axis.
struct SamplingDesc {
  GLenum minFilter = 0;
  GLenum magFilter = 0;
  GLenum wrap = 0;
};

struct Texture2DDesc {
  GLsizei width = 1, height = 1;
  GLenum internalFormat = GL_RGBA8;  // GL_SRGB8_ALPHA8, GL_RGBA16F, GL_R32UI, ...
  GLsizei levels = 1;                // 0: the full mip chain down to 1×1
  TextureData data;                  // level 0, optional
  SamplingDesc sampling;
  std::string label;
};

class Texture2D {
 public:
  Texture2D() = default;  // no GL object
  explicit Texture2D(const Texture2DDesc& desc);
  ~Texture2D();
  Texture2D(Texture2D&& other) noexcept;
  Texture2D& operator=(Texture2D&& other) noexcept;
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;

  GLuint id() const { return mId; }
  GLsizei width(GLint level = 0) const;  // of a mip level
  GLsizei height(GLint level = 0) const;
  GLsizei levels() const { return mLevels; }
  GLenum internalFormat() const { return mInternalFormat; }
  std::size_t sizeBytes() const;  // of its storage, every level (texelBytes); 0 without a GL object

  // Replaces one whole level. Throws std::invalid_argument when the byte count does not match.
  void upload(const TextureData& data, GLint level = 0);
  // Fills levels 1.. from level 0 (glGenerateTextureMipmap).
  void generateMipmaps();

  void bind(GLuint unit) const { glBindTextureUnit(unit, mId); }
  // For imageLoad/imageStore in compute: the format is the texture's internal format, which
  // must match the image's layout qualifier. `access` is GL_READ_ONLY, GL_WRITE_ONLY or
  // GL_READ_WRITE.
  void bindImage(GLuint unit, GLenum access, GLint level = 0) const;

 private:
  void release();

  GLuint mId = 0;
  GLsizei mWidth = 0, mHeight = 0, mLevels = 0;
  GLenum mInternalFormat = 0;
};

struct Texture2DArrayDesc {
  GLsizei width = 1, height = 1, layers = 1;
  GLenum internalFormat = GL_DEPTH_COMPONENT32F;
  GLsizei levels = 1;  // 0: the full mip chain
  // GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE with GL_LEQUAL, for a
  // sampler2DArrayShadow (depth formats only); linear filtering then gives 2×2 PCF.
  bool compareRefToTexture = false;
  SamplingDesc sampling;
  std::string label;
};

class Texture2DArray {
 public:
  Texture2DArray() = default;  // no GL object
  explicit Texture2DArray(const Texture2DArrayDesc& desc);
  ~Texture2DArray();
  Texture2DArray(Texture2DArray&& other) noexcept;
  Texture2DArray& operator=(Texture2DArray&& other) noexcept;
  Texture2DArray(const Texture2DArray&) = delete;
  Texture2DArray& operator=(const Texture2DArray&) = delete;

  GLuint id() const { return mId; }
  GLsizei width(GLint level = 0) const;
  GLsizei height(GLint level = 0) const;
  GLsizei layers() const { return mLayers; }
  GLsizei levels() const { return mLevels; }
  GLenum internalFormat() const { return mInternalFormat; }
  std::size_t sizeBytes() const;  // of its storage, every layer and level; 0 without a GL object

  // Replaces one whole level of every layer: layer after layer, each as TextureData's rows.
  // Throws std::invalid_argument when the byte count does not match.
  void upload(const TextureData& data, GLint level = 0);
  // Fills levels 1.. of every layer from level 0 (glGenerateTextureMipmap).
  void generateMipmaps();

  void bind(GLuint unit) const { glBindTextureUnit(unit, mId); }
  // Every layer as an image2DArray for compute (format: the internal format; access as
  // Texture2D::bindImage).
  void bindImage(GLuint unit, GLenum access, GLint level = 0) const;

 private:
  void release();

  GLuint mId = 0;
  GLsizei mWidth = 0, mHeight = 0, mLayers = 0, mLevels = 0;
  GLenum mInternalFormat = 0;
};

// Whether a sized internal format is a depth (or depth-stencil) format.
bool isDepthFormat(GLenum internalFormat);

// Bytes per texel of a sized internal format as the GL specification sizes it, for memory
// accounting: drivers may pad (RGB32F to 16 bytes, DEPTH24_STENCIL8 to 8), so this is what a
// texture needs at least. Throws std::invalid_argument for a format Prism does not use.
std::size_t texelBytes(GLenum internalFormat);

// Level `level` as `channels` floats per texel (1: red, or depth for depth formats; 2..4: RG,
// RGB, RGBA). sRGB formats come back as stored (encoded), not decoded. glGetTextureImage.
std::vector<float> readTexture2DFloat(const Texture2D& texture, int channels, GLint level = 0);
// The same for unsigned integer formats (GL_R32UI, GL_RGBA32UI, ...).
std::vector<std::uint32_t> readTexture2DUint(const Texture2D& texture, int channels = 1,
                                             GLint level = 0);
// One layer of an array: its depth for depth formats (channels 1), else `channels` floats.
// glGetTextureSubImage.
std::vector<float> readTextureLayerFloat(const Texture2DArray& texture, GLint layer,
                                         int channels = 1, GLint level = 0);

}  // namespace prism::gpu

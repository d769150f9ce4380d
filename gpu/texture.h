// A 3D texture with immutable storage over direct state access: float texels, linear filtering
// and clamp-to-edge addressing, the shape precomputed tables (upsampling coefficients, later
// the atmosphere's volumes) are sampled in. Move-only; deleted with the object.
#pragma once

#include <epoxy/gl.h>

#include <span>
#include <string>

namespace prism::gpu {

struct Texture3DDesc {
  GLsizei width = 1, height = 1, depth = 1;
  GLenum internalFormat = GL_RGB32F;
  GLenum format = GL_RGB;             // of `texels`
  std::span<const float> texels;      // width·height·depth·channels floats, x fastest
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

 private:
  GLuint mId = 0;
};

}  // namespace prism::gpu

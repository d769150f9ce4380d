// A linked GLSL program built from files: either one compute shader, or a vertex and a
// fragment shader. Sources go through assembleShaderSource() (#include with #line mapping), so
// a compile error throws GpuError(ShaderCompileFailed) whose message is the first error as
// "ORIGINAL_FILE:LINE:COLUMN: error: …" and whose log() is the driver's whole log mapped the
// same way. Move-only; the GL objects are deleted with it (a context must be current).
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <filesystem>
#include <glm/fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/shader_source.h"

namespace prism::gpu {

struct ProgramDesc {
  std::filesystem::path compute;  // either this ...
  std::filesystem::path vertex;   // ... or these two
  std::filesystem::path fragment;
  std::vector<std::filesystem::path> includeDirs;  // searched after the including file's folder
  std::vector<ShaderDefine> defines;               // inserted after #version in every stage
  std::string label;                               // glObjectLabel
};

class Program {
 public:
  Program() = default;  // no GL object
  explicit Program(const ProgramDesc& desc);
  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  GLuint id() const { return mId; }
  // Warnings the driver reported while compiling and linking (mapped), often empty.
  const std::string& log() const { return mLog; }

  void use() const { glUseProgram(mId); }

  // Throws GpuError(UniformNotFound) for a name that is not an active uniform (misspelt, or
  // optimised away because unused), instead of GL's silent location -1.
  GLint uniformLocation(std::string_view name) const;
  // Whether `name` is an active uniform: for uniforms that a variant (a #define) may drop.
  bool hasUniform(std::string_view name) const;
  // glProgramUniform*, no glUseProgram needed. Matrices are column-major, as glm stores them.
  void setUniform(std::string_view name, GLuint value) const;
  void setUniform(std::string_view name, GLint value) const;
  void setUniform(std::string_view name, GLfloat value) const;
  void setUniform(std::string_view name, const glm::vec2& value) const;
  void setUniform(std::string_view name, const glm::vec3& value) const;
  void setUniform(std::string_view name, const glm::vec4& value) const;
  void setUniform(std::string_view name, const glm::ivec2& value) const;
  void setUniform(std::string_view name, const glm::ivec3& value) const;
  void setUniform(std::string_view name, const glm::mat3& value) const;
  void setUniform(std::string_view name, const glm::mat4& value) const;

  // local_size_x/y/z of a compute program.
  std::array<GLuint, 3> workGroupSize() const;

 private:
  void release();  // deletes the program, if any

  GLuint mId = 0;
  std::string mLog;
};

}  // namespace prism::gpu

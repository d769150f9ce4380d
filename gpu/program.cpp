#include "gpu/program.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <utility>

#include "gpu/error.h"
#include "gpu/object_counter.h"

namespace prism::gpu {
namespace {

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) glGetShaderInfoLog(shader, length, nullptr, log.data());
  while (!log.empty() && log.back() == '\0') log.pop_back();
  return log;
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) glGetProgramInfoLog(program, length, nullptr, log.data());
  while (!log.empty() && log.back() == '\0') log.pop_back();
  return log;
}

struct Stage {
  GLenum type;
  const std::filesystem::path* file;
};

// Compiles one stage; on failure deletes it and throws with the log mapped to original files.
GLuint compile(const Stage& stage, const ProgramDesc& desc, std::string& warnings) {
  ShaderSource source = assembleShaderSource(*stage.file, desc.includeDirs, desc.defines);
  GLuint shader = glCreateShader(stage.type);
  const GLchar* text = source.text.c_str();
  const auto length = static_cast<GLint>(source.text.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  std::string mapped = mapShaderLog(shaderLog(shader), source.files);
  if (!ok) {
    glDeleteShader(shader);
    std::string first = firstErrorLine(mapped);
    if (first.empty()) first = stage.file->string() + ": error: compilation failed (empty log)";
    throw GpuError(Diagnostic::ShaderCompileFailed, first, mapped);
  }
  warnings += mapped;
  return shader;
}

}  // namespace

Program::Program(const ProgramDesc& desc) {
  std::vector<Stage> stages;
  if (!desc.compute.empty()) stages.push_back({GL_COMPUTE_SHADER, &desc.compute});
  if (!desc.vertex.empty()) stages.push_back({GL_VERTEX_SHADER, &desc.vertex});
  if (!desc.fragment.empty()) stages.push_back({GL_FRAGMENT_SHADER, &desc.fragment});
  bool compute = !desc.compute.empty();
  bool draw = !desc.vertex.empty() && !desc.fragment.empty();
  if (compute == draw || stages.size() != (compute ? 1u : 2u))
    throw GpuError(Diagnostic::ProgramStagesInvalid,
                   "prism::gpu::Program: give either a compute shader or a vertex and a fragment "
                   "shader" +
                       (desc.label.empty() ? std::string() : " (" + desc.label + ")"));

  std::vector<GLuint> shaders;
  try {
    for (const Stage& stage : stages) shaders.push_back(compile(stage, desc, mLog));
  } catch (...) {
    for (GLuint s : shaders) glDeleteShader(s);
    throw;
  }
  mId = glCreateProgram();
  if (!desc.label.empty())
    glObjectLabel(GL_PROGRAM, mId, static_cast<GLsizei>(desc.label.size()), desc.label.data());
  for (GLuint s : shaders) glAttachShader(mId, s);
  glLinkProgram(mId);
  for (GLuint s : shaders) {
    glDetachShader(mId, s);
    glDeleteShader(s);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(mId, GL_LINK_STATUS, &ok);
  std::string log = programLog(mId);
  if (!ok) {
    glDeleteProgram(mId);
    mId = 0;
    std::string files;
    for (const Stage& stage : stages) files += (files.empty() ? "" : ", ") + stage.file->string();
    std::string first = firstErrorLine(log);
    throw GpuError(Diagnostic::ProgramLinkFailed,
                   files + ": error: link failed" + (first.empty() ? "" : ": " + first), log);
  }
  mLog += log;
  countGlObjects(GlObjectKind::Program, 1);
}

Program::~Program() { release(); }

void Program::release() {
  if (!mId) return;
  glDeleteProgram(mId);
  countGlObjects(GlObjectKind::Program, -1);
  mId = 0;
}

Program::Program(Program&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mLog(std::move(other.mLog)) {}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mLog = std::move(other.mLog);
  }
  return *this;
}

GLint Program::uniformLocation(std::string_view name) const {
  std::string n(name);
  GLint location = glGetUniformLocation(mId, n.c_str());
  if (location < 0)
    throw GpuError(Diagnostic::UniformNotFound,
                   "prism::gpu::Program: '" + n + "' is not an active uniform");
  return location;
}

bool Program::hasUniform(std::string_view name) const {
  return glGetUniformLocation(mId, std::string(name).c_str()) >= 0;
}

void Program::setUniform(std::string_view name, GLuint value) const {
  glProgramUniform1ui(mId, uniformLocation(name), value);
}

void Program::setUniform(std::string_view name, GLint value) const {
  glProgramUniform1i(mId, uniformLocation(name), value);
}

void Program::setUniform(std::string_view name, GLfloat value) const {
  glProgramUniform1f(mId, uniformLocation(name), value);
}

void Program::setUniform(std::string_view name, const glm::vec2& value) const {
  glProgramUniform2fv(mId, uniformLocation(name), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view name, const glm::vec3& value) const {
  glProgramUniform3fv(mId, uniformLocation(name), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view name, const glm::vec4& value) const {
  glProgramUniform4fv(mId, uniformLocation(name), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view name, const glm::ivec2& value) const {
  glProgramUniform2iv(mId, uniformLocation(name), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view name, const glm::ivec3& value) const {
  glProgramUniform3iv(mId, uniformLocation(name), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view name, const glm::mat3& value) const {
  glProgramUniformMatrix3fv(mId, uniformLocation(name), 1, GL_FALSE, glm::value_ptr(value));
}

void Program::setUniform(std::string_view name, const glm::mat4& value) const {
  glProgramUniformMatrix4fv(mId, uniformLocation(name), 1, GL_FALSE, glm::value_ptr(value));
}

std::array<GLuint, 3> Program::workGroupSize() const {
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(mId, GL_COMPUTE_WORK_GROUP_SIZE, size);
  return {static_cast<GLuint>(size[0]), static_cast<GLuint>(size[1]), static_cast<GLuint>(size[2])};
}

}  // namespace prism::gpu

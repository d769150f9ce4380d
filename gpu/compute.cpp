#include "gpu/compute.h"

#include <stdexcept>
#include <string>
#include <string_view>

namespace prism::gpu {

void runCompute(const Program& program, WorkGroups groups, GLbitfield barriers) {
  const GLuint count[3] = {groups.x, groups.y, groups.z};
  for (GLuint axis = 0; axis < 3; ++axis) {
    GLint limit = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &limit);
    if (count[axis] == 0 || count[axis] > static_cast<GLuint>(limit))
      throw std::invalid_argument("prism::gpu::runCompute: " + std::to_string(count[axis]) +
                                  " work groups along axis " + std::to_string(axis) +
                                  " (allowed 1.." + std::to_string(limit) + ")");
  }
  program.use();
  glDispatchCompute(groups.x, groups.y, groups.z);
  if (barriers) glMemoryBarrier(barriers);
}

void runCompute1D(const Program& program, std::size_t invocations, GLbitfield barriers) {
  std::size_t local = program.workGroupSize()[0];
  if (local == 0) throw std::invalid_argument("prism::gpu::runCompute1D: not a compute program");
  std::size_t groups = (invocations + local - 1) / local;
  if (groups > 0xffffffffu)
    throw std::invalid_argument("prism::gpu::runCompute1D: too many invocations");
  runCompute(program, {static_cast<GLuint>(groups), 1, 1}, barriers);
}

std::optional<long> shaderLoopIterationLimit() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer != nullptr && std::string_view(renderer).starts_with("llvmpipe")) return 65535;
  return std::nullopt;
}

}  // namespace prism::gpu

// Dispatching compute programs. Buffers are bound by the caller (Buffer::bindBase); the
// barrier after the dispatch makes the results visible to what usually follows: another
// dispatch reading the SSBOs, or glGetNamedBufferSubData (Buffer::read).
#pragma once

#include <epoxy/gl.h>

#include <cstddef>

#include "gpu/program.h"

namespace prism::gpu {

struct WorkGroups {
  GLuint x = 1, y = 1, z = 1;
};

constexpr GLbitfield kDefaultComputeBarriers =
    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;

// glUseProgram + glDispatchCompute(groups) + glMemoryBarrier(barriers). Throws
// std::invalid_argument for a count of zero or above GL_MAX_COMPUTE_WORK_GROUP_COUNT.
void runCompute(const Program& program, WorkGroups groups,
                GLbitfield barriers = kDefaultComputeBarriers);

// Enough groups along x for `invocations` threads of the program's local_size_x (the kernel
// must ignore the surplus invocations of the last group).
void runCompute1D(const Program& program, std::size_t invocations,
                  GLbitfield barriers = kDefaultComputeBarriers);

}  // namespace prism::gpu

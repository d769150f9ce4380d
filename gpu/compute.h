// Dispatching compute programs. Buffers are bound by the caller (Buffer::bindBase); the
// barrier after the dispatch makes the results visible to what usually follows: another
// dispatch reading the SSBOs, or glGetNamedBufferSubData (Buffer::read).
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <optional>

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

// Loop iterations one invocation may run, all its loops together, before the current context's
// driver stops them and lets the shader go on with partial sums: 65 535 on Mesa's llvmpipe
// (LP_MAX_TGSI_LOOP_ITERATIONS), none elsewhere. A long march splits its work to stay within it
// (techniques/nebula/gpu/nebula_march_segments.h).
std::optional<long> shaderLoopIterationLimit();

}  // namespace prism::gpu

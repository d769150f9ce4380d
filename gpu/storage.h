// Making a GL object's immutable storage (glNamedBufferStorage, glTextureStorage*): the call runs
// with the driver's error messages muted (a debug group), and its failure — running out of
// memory, above all — is one GpuError naming the object. Unmuted, `prism demo` at 16 384² on
// llvmpipe printed the driver's KHR_debug line, then an incomplete framebuffer's, then the error:
// three lines for one failure; a buffer that failed went on as a broken object, and the command
// ended in an internal error.
#pragma once

#include <functional>
#include <string>

#include "gpu/diagnostics.h"

namespace prism::gpu {

// Throws GpuError(id, "WHAT: out of GPU memory (a smaller size may fit)"), or "WHAT: the driver
// refused its storage (GL error N)", when `storage` leaves a GL error.
void makeStorage(Diagnostic id, const std::string& what, const std::function<void()>& storage);

}  // namespace prism::gpu

#include "gpu/storage.h"

#include <epoxy/gl.h>

#include "gpu/error.h"

namespace prism::gpu {

void makeStorage(Diagnostic id, const std::string& what, const std::function<void()>& storage) {
  // Earlier errors were reported where they happened (the debug output): not this call's.
  while (glGetError() != GL_NO_ERROR) {
  }
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "storage");
  glDebugMessageControl(GL_DEBUG_SOURCE_API, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  storage();
  const GLenum error = glGetError();
  glPopDebugGroup();
  if (error == GL_NO_ERROR) return;
  throw GpuError(id, error == GL_OUT_OF_MEMORY ? what + ": out of GPU memory (a smaller size may fit)"
                                               : what + ": the driver refused its storage (GL error " +
                                                     std::to_string(error) + ")");
}

}  // namespace prism::gpu

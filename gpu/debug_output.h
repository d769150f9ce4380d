// KHR_debug (core since OpenGL 4.3): the driver's own messages about API errors, undefined
// behaviour and slow paths, routed to a sink the caller chooses. Each message carries a stable
// Diagnostic (GlDebugError, GlDebugWarning, GlDebugInfo) derived from its type and severity, so
// that tests can count errors. Output is synchronous: the sink runs inside the GL call that
// caused the message, on the calling thread, so a debugger breakpoint in it shows the culprit.
#pragma once

#include <epoxy/gl.h>

#include <functional>
#include <string>

#include "gpu/diagnostics.h"

namespace prism::gpu {

struct DebugMessage {
  Diagnostic id = Diagnostic::GlDebugInfo;
  GLenum source = 0;    // GL_DEBUG_SOURCE_*
  GLenum type = 0;      // GL_DEBUG_TYPE_*
  GLenum severity = 0;  // GL_DEBUG_SEVERITY_*
  GLuint glId = 0;      // the driver's own message id (not stable across drivers)
  std::string text;
};

using DebugSink = std::function<void(const DebugMessage&)>;

// "prism gpu: GlDebugError: api error 1282, high: <text>" on one line.
std::string formatDebugMessage(const DebugMessage& message);
// The default sink: formatDebugMessage() on stderr.
void printDebugMessage(const DebugMessage& message);

// Installs the debug callback on the context current at construction and removes it at
// destruction (which must happen while that context is still current). Not movable: the
// driver holds its address.
class DebugOutput {
 public:
  // Notifications (GL_DEBUG_SEVERITY_NOTIFICATION) are filtered out unless asked for.
  explicit DebugOutput(bool notifications = false);
  ~DebugOutput();
  DebugOutput(const DebugOutput&) = delete;
  DebugOutput& operator=(const DebugOutput&) = delete;

  // An empty sink restores the default (printDebugMessage). Returns the previous sink.
  DebugSink setSink(DebugSink sink);

 private:
  static void GLAPIENTRY callback(GLenum source, GLenum type, GLuint id, GLenum severity,
                                  GLsizei length, const GLchar* message, const void* self);
  DebugSink mSink;
};

}  // namespace prism::gpu

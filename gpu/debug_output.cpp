#include "gpu/debug_output.h"

#include <cstdio>
#include <utility>

namespace prism::gpu {
namespace {

Diagnostic classify(GLenum type, GLenum severity) {
  if (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR)
    return Diagnostic::GlDebugError;
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION || type == GL_DEBUG_TYPE_MARKER ||
      type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP)
    return Diagnostic::GlDebugInfo;
  return Diagnostic::GlDebugWarning;
}

const char* sourceName(GLenum source) {
  switch (source) {
    case GL_DEBUG_SOURCE_API: return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
  }
}

const char* typeName(GLenum type) {
  switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    case GL_DEBUG_TYPE_MARKER: return "marker";
    case GL_DEBUG_TYPE_PUSH_GROUP: return "push group";
    case GL_DEBUG_TYPE_POP_GROUP: return "pop group";
    default: return "other";
  }
}

const char* severityName(GLenum severity) {
  switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH: return "high";
    case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
    case GL_DEBUG_SEVERITY_LOW: return "low";
    default: return "notification";
  }
}

}  // namespace

std::string formatDebugMessage(const DebugMessage& m) {
  std::string text = m.text;
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return "prism gpu: " + std::string(diagnosticName(m.id)) + ": " + sourceName(m.source) + " " +
         typeName(m.type) + " " + std::to_string(m.glId) + ", " + severityName(m.severity) + ": " +
         text;
}

void printDebugMessage(const DebugMessage& message) {
  std::fprintf(stderr, "%s\n", formatDebugMessage(message).c_str());
}

DebugOutput::DebugOutput(bool notifications) : mSink(printDebugMessage) {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(&DebugOutput::callback, this);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  if (!notifications)
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                          GL_FALSE);
}

DebugOutput::~DebugOutput() { glDebugMessageCallback(nullptr, nullptr); }

DebugSink DebugOutput::setSink(DebugSink sink) {
  DebugSink previous = std::move(mSink);
  mSink = sink ? std::move(sink) : DebugSink(printDebugMessage);
  return previous;
}

void GLAPIENTRY DebugOutput::callback(GLenum source, GLenum type, GLuint id, GLenum severity,
                                      GLsizei length, const GLchar* message, const void* self) {
  // Called from inside the driver's C code: nothing may unwind through it.
  try {
    DebugMessage m{classify(type, severity), source, type, severity, id,
                   length >= 0 ? std::string(message, static_cast<std::size_t>(length))
                               : std::string(message)};
    static_cast<const DebugOutput*>(self)->mSink(m);
  } catch (...) {
    std::fputs("prism: a KHR_debug sink threw; message dropped\n", stderr);
  }
}

}  // namespace prism::gpu

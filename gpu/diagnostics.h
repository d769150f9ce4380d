// Stable diagnostic ids for everything the GPU layer reports (STYLE.md §11, after sokol's
// SG_LOGITEM_*): shader and program failures, include errors, context creation and the
// driver's KHR_debug messages. The list below is the only place an id is defined; tests assert
// on ids, never on message text, so messages may improve without breaking them. Append new ids
// at the end so that the numeric values stay stable too.
#pragma once

#include <string_view>

namespace prism::gpu {

// X(Name, one-line meaning)
#define PRISM_GPU_DIAGNOSTICS(X)                                                                \
  X(ContextUnavailable, "no usable OpenGL 4.5 core context could be created through EGL")       \
  X(ShaderFileNotFound, "a shader source file does not exist or cannot be read")                \
  X(MissingVersion, "a shader's root file has no #version directive")                           \
  X(IncludeMalformed, "an #include line is not of the form #include \"name\"")                  \
  X(IncludeNotFound, "an #include names a file found in no include folder")                     \
  X(IncludeCycle, "a file #includes itself, directly or through others")                        \
  X(ShaderCompileFailed, "the driver rejected a shader stage")                                  \
  X(ProgramLinkFailed, "the driver could not link the program's stages")                        \
  X(ProgramStagesInvalid, "a program description names no stage or mixes compute and draw")     \
  X(UniformNotFound, "a uniform name is not an active uniform of the program")                  \
  X(GlDebugError, "KHR_debug: an API error or undefined behaviour reported by the driver")      \
  X(GlDebugWarning, "KHR_debug: a deprecated, non-portable or slow use reported by the driver") \
  X(GlDebugInfo, "KHR_debug: a notification from the driver or the application")                \
  X(FramebufferIncomplete, "the attachments do not make a complete framebuffer")                \
  X(NoOpenGl45, "no window with an OpenGL 4.5 core context could be created through GLFW")       \
  X(TextureStorageFailed, "the driver could not make a texture's storage (out of memory, above all)") \
  X(BufferStorageFailed, "the driver could not make a buffer's storage (out of memory, above all)")

enum class Diagnostic {
#define PRISM_GPU_DIAGNOSTIC_ENUM(name, meaning) name,
  PRISM_GPU_DIAGNOSTICS(PRISM_GPU_DIAGNOSTIC_ENUM)
#undef PRISM_GPU_DIAGNOSTIC_ENUM
};

// The id's name as written above, e.g. "ShaderCompileFailed".
constexpr std::string_view diagnosticName(Diagnostic id) {
  switch (id) {
#define PRISM_GPU_DIAGNOSTIC_NAME(name, meaning) \
  case Diagnostic::name: return #name;
    PRISM_GPU_DIAGNOSTICS(PRISM_GPU_DIAGNOSTIC_NAME)
#undef PRISM_GPU_DIAGNOSTIC_NAME
  }
  return "UnknownDiagnostic";
}

// The id's one-line meaning.
constexpr std::string_view diagnosticMeaning(Diagnostic id) {
  switch (id) {
#define PRISM_GPU_DIAGNOSTIC_MEANING(name, meaning) \
  case Diagnostic::name: return meaning;
    PRISM_GPU_DIAGNOSTICS(PRISM_GPU_DIAGNOSTIC_MEANING)
#undef PRISM_GPU_DIAGNOSTIC_MEANING
  }
  return "";
}

}  // namespace prism::gpu

// GLSL source assembly: resolves `#include "name"` (GLSL itself has none without
// ARB_shading_language_include) and maps driver logs back to the original files.
//
// Every distinct file gets a GLSL source-string number (the root is 0) and the assembled text
// carries `#line L S` directives, so the driver reports "S:L" and mapShaderLog() rewrites that
// to "path:L". A name is looked up beside the file that includes it, then in each include
// folder in order (`#include "prelude.glsl"` from a kernel finds shaders/shared/prelude.glsl).
// Including a file again is allowed (guard it with #ifndef if it defines things); including
// a file that is still open is a cycle and an error. Lines are matched textually: an #include
// inside a comment or an inactive #if branch is still resolved.
// `#extension GL_GOOGLE_include_directive : …` lines are dropped, so that the same file can be
// checked offline with glslangValidator -I.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace prism::gpu {

struct ShaderDefine {
  std::string name;
  std::string value;  // may be empty: `#define NAME`
};

struct ShaderSource {
  std::string text;                          // what the driver compiles
  std::vector<std::filesystem::path> files;  // source-string number -> original file
};

// Reads `file` and everything it includes. Defines are inserted right after the root's
// #version line (which must exist); line numbers are unaffected. Throws GpuError with
// ShaderFileNotFound, MissingVersion, IncludeMalformed, IncludeNotFound or IncludeCycle; the
// message names the including file and line.
ShaderSource assembleShaderSource(const std::filesystem::path& file,
                                  std::span<const std::filesystem::path> includeDirs,
                                  std::span<const ShaderDefine> defines = {});

// Rewrites the source references of a driver's info log to "path:line[:column]": Mesa's
// "S:L(C): error: …", the "ERROR: S:L: …" / "WARNING: S:L: …" form of glslang-derived
// drivers, and NVIDIA's "S(L) : error …". Other lines pass unchanged.
std::string mapShaderLog(std::string_view log, std::span<const std::filesystem::path> files);

// The first line of a mapped log that reports an error (else its first non-empty line).
std::string firstErrorLine(std::string_view mappedLog);

}  // namespace prism::gpu

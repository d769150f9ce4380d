#include "gpu/headless_context.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gpu/error.h"
#include "gpu/gpu_test_support.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

TEST_F(GpuTest, ContextIsOpenGl45CoreWithComputeAndStrings) {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_FALSE(context().renderer().empty());
  EXPECT_FALSE(context().vendor().empty());
  EXPECT_NE(context().version().find("4."), std::string::npos) << context().version();
  EXPECT_FALSE(context().glslVersion().empty());
  EXPECT_TRUE(context().platform() == "surfaceless" || context().platform().starts_with("device"))
      << context().platform();
  GLint invocations = 0;
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  EXPECT_GE(invocations, 1024);  // the GL 4.5 minimum
  std::printf("renderer: %s | version: %s | GLSL %s | platform %s\n", context().renderer().c_str(),
              context().version().c_str(), context().glslVersion().c_str(),
              context().platform().c_str());
}

TEST_F(GpuTest, DebugOutputReportsAnApiErrorWithItsDiagnostic) {
  GLuint neverCreated = 0xdeadu;
  GLint value = 0;
  glGetNamedBufferParameteriv(neverCreated, GL_BUFFER_SIZE, &value);  // GL_INVALID_OPERATION
  std::vector<DebugMessage> errors = takeDebugErrors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, Diagnostic::GlDebugError);
  EXPECT_EQ(errors[0].type, static_cast<GLenum>(GL_DEBUG_TYPE_ERROR));
  EXPECT_EQ(errors[0].source, static_cast<GLenum>(GL_DEBUG_SOURCE_API));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  std::string line = formatDebugMessage(errors[0]);
  EXPECT_TRUE(line.starts_with("prism gpu: GlDebugError: api error ")) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

TEST_F(GpuTest, DebugSinkSeesApplicationMessagesAsInfoOrWarning) {
  std::vector<DebugMessage> seen;
  DebugSink previous =
      context().debugOutput().setSink([&](const DebugMessage& m) { seen.push_back(m); });
  const std::string text = "prism test marker";
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PERFORMANCE, 7,
                       GL_DEBUG_SEVERITY_MEDIUM, static_cast<GLsizei>(text.size()), text.c_str());
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 8, GL_DEBUG_SEVERITY_HIGH,
                       static_cast<GLsizei>(text.size()), text.c_str());
  context().debugOutput().setSink(std::move(previous));
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].id, Diagnostic::GlDebugWarning);
  EXPECT_EQ(seen[0].glId, 7u);
  EXPECT_EQ(seen[0].text, text);
  EXPECT_EQ(seen[1].id, Diagnostic::GlDebugInfo);
}

TEST_F(GpuTest, TwoContextsOnOneThreadShareTheDisplaySafely) {
  GLuint first = 0;
  glCreateBuffers(1, &first);
  {
    HeadlessContext second;  // now current; the fixture's context is no longer
    EXPECT_EQ(second.renderer(), context().renderer());
    EXPECT_FALSE(glIsBuffer(first));  // separate, unshared name spaces
  }
  // Destroying `second` must leave the display they share usable.
  context().makeCurrent();
  EXPECT_TRUE(glIsBuffer(first));
  glDeleteBuffers(1, &first);
}

// Without an EGL vendor (glvnd told to load none) the constructor must fail with the one-line
// message the CLI prints. In a child process that re-executes this test alone, so that no EGL
// state from earlier tests is inherited.
TEST(HeadlessContextDeathTest, NoEglVendorGivesOneLineWithThePackagesToInstall) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/prism_no_vendor.json", 1);
        try {
          HeadlessContext context;
        } catch (const GpuError& e) {
          std::string message = e.what();
          bool good = e.id() == Diagnostic::ContextUnavailable &&
                      message.find('\n') == std::string::npos &&
                      message.find("libegl-mesa0 libgl1-mesa-dri libegl1") != std::string::npos;
          std::fprintf(stderr, "%s\n", message.c_str());
          std::exit(good ? 0 : 1);
        }
        std::exit(2);
      },
      ::testing::ExitedWithCode(0), "no usable OpenGL 4.5 core context");
}

TEST(Diagnostics, NamesComeFromTheOneList) {
  EXPECT_EQ(diagnosticName(Diagnostic::ContextUnavailable), "ContextUnavailable");
  EXPECT_EQ(diagnosticName(Diagnostic::ShaderCompileFailed), "ShaderCompileFailed");
  EXPECT_EQ(diagnosticName(Diagnostic::IncludeCycle), "IncludeCycle");
  EXPECT_EQ(diagnosticName(Diagnostic::GlDebugError), "GlDebugError");
  EXPECT_FALSE(diagnosticMeaning(Diagnostic::IncludeNotFound).empty());
  GpuError e(Diagnostic::ProgramLinkFailed, "a.comp: error: link failed", "full log");
  EXPECT_EQ(e.id(), Diagnostic::ProgramLinkFailed);
  EXPECT_EQ(e.log(), "full log");
}

}  // namespace
}  // namespace prism::gpu

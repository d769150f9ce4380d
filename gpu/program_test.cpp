// Programs through the driver: the loader's output compiles and runs, and compile errors come
// back as ORIGINAL_FILE:LINE, with stable diagnostic ids.
#include "gpu/program.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute.h"
#include "gpu/error.h"
#include "gpu/gpu_test_support.h"

namespace prism::gpu {
namespace {

namespace fs = std::filesystem;
using testing::GpuTest;

using testing::lineOf;
using testing::loaderPath;

ProgramDesc computeDesc(const std::string& name) {
  ProgramDesc desc;
  desc.compute = loaderPath(name);
  desc.includeDirs = testing::sharedIncludeDirs();
  desc.includeDirs.push_back(loaderPath("other"));
  return desc;
}

// Builds `desc`, expecting a GpuError; returns it (or a default one after a test failure).
GpuError expectError(const ProgramDesc& desc) {
  try {
    Program program(desc);
  } catch (const GpuError& e) {
    return e;
  }
  ADD_FAILURE() << "the program built";
  return GpuError(Diagnostic::GlDebugInfo, "");
}

TEST_F(GpuTest, ProgramWithIncludesRunsAndComputesTheExpectedValue) {
  Program program(computeDesc("main.comp"));
  Buffer result({sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT, "result"});
  result.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  EXPECT_EQ(program.workGroupSize(), (std::array<GLuint, 3>{1, 1, 1}));
  runCompute(program, {1, 1, 1});
  EXPECT_EQ(result.read<GLuint>(), std::vector<GLuint>{41u + 80u + 1000u});
}

TEST_F(GpuTest, CompileErrorInAnIncludedFileNamesThatFileAndLine) {
  ProgramDesc desc = computeDesc("broken_root.comp");
  fs::path body = loaderPath("broken_body.glsl");
  std::string where = body.string() + ":" + std::to_string(lineOf(body, "BROKEN:")) + ":";
  for (bool withDefines : {false, true}) {
    if (withDefines) desc.defines = {{"UNUSED_ONE", "1"}, {"UNUSED_TWO", ""}};
    GpuError e = expectError(desc);
    EXPECT_EQ(e.id(), Diagnostic::ShaderCompileFailed);
    EXPECT_TRUE(std::string(e.what()).starts_with(where)) << e.what() << "\nlog:\n" << e.log();
    EXPECT_NE(std::string(e.what()).find("error"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    EXPECT_NE(e.log().find(where), std::string::npos) << e.log();
  }
  takeDebugErrors();  // the driver may also report the failed compile through KHR_debug
}

TEST_F(GpuTest, CompileErrorAfterAnIncludeNamesTheRootFileLine) {
  ProgramDesc desc = computeDesc("broken_after_include.comp");
  desc.defines = {{"SOME_OPTION", "2"}};
  std::string where =
      desc.compute.string() + ":" + std::to_string(lineOf(desc.compute, "BROKEN:")) + ":";
  GpuError e = expectError(desc);
  EXPECT_EQ(e.id(), Diagnostic::ShaderCompileFailed);
  EXPECT_TRUE(std::string(e.what()).starts_with(where)) << e.what() << "\nlog:\n" << e.log();
  EXPECT_NE(std::string(e.what()).find("undeclaredName"), std::string::npos) << e.what();
  takeDebugErrors();
}

TEST_F(GpuTest, LoaderErrorsSurfaceFromProgramWithTheirIds) {
  EXPECT_EQ(expectError(computeDesc("missing_include.comp")).id(), Diagnostic::IncludeNotFound);
  EXPECT_EQ(expectError(computeDesc("cycle_root.comp")).id(), Diagnostic::IncludeCycle);
  EXPECT_EQ(expectError(computeDesc("not_there.comp")).id(), Diagnostic::ShaderFileNotFound);
  EXPECT_EQ(expectError(ProgramDesc{}).id(), Diagnostic::ProgramStagesInvalid);
  ProgramDesc both = computeDesc("main.comp");
  both.vertex = loaderPath("triangle.vert");
  both.fragment = loaderPath("triangle.frag");
  EXPECT_EQ(expectError(both).id(), Diagnostic::ProgramStagesInvalid);
}

TEST_F(GpuTest, LinkFailureHasItsOwnId) {
  GpuError e = expectError(computeDesc("no_main.comp"));
  EXPECT_EQ(e.id(), Diagnostic::ProgramLinkFailed);
  EXPECT_NE(std::string(e.what()).find("no_main.comp: error: link failed"), std::string::npos)
      << e.what();
  takeDebugErrors();
}

TEST_F(GpuTest, DrawProgramLinksAndUniformsAreCheckedByName) {
  ProgramDesc desc;
  desc.vertex = loaderPath("triangle.vert");
  desc.fragment = loaderPath("triangle.frag");
  desc.includeDirs = testing::sharedIncludeDirs();
  desc.defines = {{"FRAGMENT_BLUE", "0.25f"}};
  desc.label = "triangle";
  Program program(desc);
  EXPECT_NE(program.id(), 0u);
  try {
    program.uniformLocation("uNoSuchUniform");
    ADD_FAILURE() << "no error";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::UniformNotFound);
  }
  Program moved(std::move(program));
  EXPECT_EQ(program.id(), 0u);  // NOLINT(bugprone-use-after-move)
  EXPECT_TRUE(glIsProgram(moved.id()));
}

TEST_F(GpuTest, VectorAndMatrixUniformsArriveColumnMajor) {
  Program program = testing::parityKernel("uniforms.comp");
  EXPECT_FALSE(program.hasUniform("uOptional"));
  EXPECT_TRUE(program.hasUniform("uM4"));
  glm::mat3 m3;
  glm::mat4 m4;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      if (c < 3 && r < 3) m3[c][r] = static_cast<float>(10 * c + r);
      m4[c][r] = static_cast<float>(100 + 10 * c + r);
    }
  program.setUniform("uV2", glm::vec2(1.0f, 2.0f));
  program.setUniform("uV3", glm::vec3(3.0f, 4.0f, 5.0f));
  program.setUniform("uV4", glm::vec4(6.0f, 7.0f, 8.0f, 9.0f));
  program.setUniform("uI2", glm::ivec2(-10, 11));
  program.setUniform("uM3", m3);
  program.setUniform("uM4", m4);
  Buffer out({36 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT, "uniforms"});
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  runCompute(program, {1, 1, 1});
  std::vector<float> expected{1, 2, 3, 4, 5, 6, 7, 8, 9, -10, 11};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) expected.push_back(static_cast<float>(10 * c + r));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) expected.push_back(static_cast<float>(100 + 10 * c + r));
  EXPECT_EQ(out.read<float>(), expected);

  Program optional = testing::parityKernel("uniforms.comp", {{"WITH_OPTIONAL", ""}});
  EXPECT_TRUE(optional.hasUniform("uOptional"));
}

TEST_F(GpuTest, RunComputeRejectsEmptyAndOversizedDispatches) {
  Program program(computeDesc("main.comp"));
  EXPECT_THROW(runCompute(program, {0, 1, 1}), std::invalid_argument);
  GLint limit = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 1, &limit);
  EXPECT_THROW(runCompute(program, {1, static_cast<GLuint>(limit) + 1u, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace prism::gpu

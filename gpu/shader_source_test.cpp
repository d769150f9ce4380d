// The #include loader without a driver: resolution order, #line bookkeeping (checked by
// replaying the directives), and the errors for missing, malformed and cyclic includes.
#include "gpu/shader_source.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gpu/error.h"
#include "gpu/gpu_test_support.h"
#include "core/data_files.h"

namespace prism::gpu {
namespace {

namespace fs = std::filesystem;

using testing::lineOf;
using testing::loaderPath;

std::vector<fs::path> includeDirs() {
  std::vector<fs::path> dirs = testing::sharedIncludeDirs();
  dirs.push_back(loaderPath("other"));
  return dirs;
}

std::vector<std::string> lines(std::istream& in) {
  std::vector<std::string> result;
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

std::vector<std::string> fileLines(const fs::path& file) {
  std::ifstream in(file);
  return lines(in);
}

// Replays the #line directives of an assembled source the way a GLSL ≥ 3.30 compiler does and
// checks that every other line is, verbatim, the line of the original file it claims to be.
// Returns how many lines were checked.
std::size_t expectLinesMapBack(const ShaderSource& source) {
  std::istringstream in(source.text);
  std::map<fs::path, std::vector<std::string>> originals;
  std::size_t sourceNumber = 0, line = 1, checked = 0;
  for (const std::string& text : lines(in)) {
    if (text.starts_with("#line ")) {  // "#line L S", as the loader writes it
      std::istringstream directive(text.substr(6));
      directive >> line >> sourceNumber;
      EXPECT_TRUE(directive && directive.eof()) << text;
      continue;
    }
    if (text.starts_with("#define ") && sourceNumber == 0 && line == 2) continue;  // injected
    EXPECT_LT(sourceNumber, source.files.size());
    if (sourceNumber >= source.files.size()) return checked;
    const fs::path& file = source.files[sourceNumber];
    auto [it, fresh] = originals.try_emplace(file);
    if (fresh) it->second = fileLines(file);
    EXPECT_LE(line, it->second.size()) << file;
    if (line <= it->second.size()) {
      const std::string& original = it->second[line - 1];
      bool dropped =
          text.empty() && original.find("GL_GOOGLE_include_directive") != std::string::npos;
      if (!dropped) {
        EXPECT_EQ(text, original) << file << ":" << line;
      }
      ++checked;
    }
    ++line;
  }
  return checked;
}

TEST(ShaderSource, ResolvesIncludesAndEveryLineMapsBackToItsFile) {
  ShaderSource source = assembleShaderSource(loaderPath("main.comp"), includeDirs());
  EXPECT_EQ(source.text.find("#include"), std::string::npos);
  ASSERT_GE(source.files.size(), 5u);
  EXPECT_EQ(source.files[0], loaderPath("main.comp"));
  // Each file once in the table, in first-inclusion order (the prelude includes the shared
  // constants beside it); lib/second.glsl was included twice.
  std::vector<fs::path> expected{
      loaderPath("main.comp"), testing::sharedIncludeDirs()[0] / "prelude.glsl",
      testing::sharedIncludeDirs()[0] / "constants.glsl", loaderPath("lib/first.glsl"), loaderPath("lib/second.glsl"), loaderPath("shadow.glsl")};
  EXPECT_EQ(source.files, expected);
  EXPECT_EQ(source.text.find("return 7u"), std::string::npos) << "other/shadow.glsl chosen";
  EXPECT_GT(expectLinesMapBack(source), 20u);
}

TEST(ShaderSource, DefinesGoRightAfterVersionWithoutShiftingLines) {
  std::vector<ShaderDefine> defines{{"FRAGMENT_BLUE", "0.5f"}, {"FLAG", ""}};
  ShaderSource source = assembleShaderSource(loaderPath("triangle.frag"), {}, defines);
  EXPECT_TRUE(source.text.starts_with(
      "#version 450\n#define FRAGMENT_BLUE 0.5f\n#define FLAG\n#line 2 0\n"))
      << source.text;
  EXPECT_GT(expectLinesMapBack(source), 4u);
}

TEST(ShaderSource, MissingIncludeNamesTheIncluderLineAndTheFoldersSearched) {
  fs::path root = loaderPath("missing_include.comp");
  try {
    assembleShaderSource(root, includeDirs());
    FAIL() << "no error";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::IncludeNotFound);
    std::string where = root.string() + ":" + std::to_string(lineOf(root, "MISSING")) + ": error: ";
    EXPECT_TRUE(std::string(e.what()).starts_with(where)) << e.what();
    EXPECT_NE(std::string(e.what()).find("does_not_exist.glsl"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find(includeDirs()[1].string()), std::string::npos);
  }
}

TEST(ShaderSource, IncludeCycleIsAnErrorNotAHang) {
  fs::path b = loaderPath("cycle_b.glsl");
  try {
    assembleShaderSource(loaderPath("cycle_root.comp"), {});
    FAIL() << "no error";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::IncludeCycle);
    std::string where = b.string() + ":" + std::to_string(lineOf(b, "CYCLE")) + ": error: ";
    EXPECT_TRUE(std::string(e.what()).starts_with(where)) << e.what();
    EXPECT_NE(std::string(e.what()).find("cycle_a.glsl -> " + b.string() + " -> "),
              std::string::npos)
        << e.what();
  }
  try {
    assembleShaderSource(loaderPath("self_include.comp"), {});
    FAIL() << "no error";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::IncludeCycle) << e.what();
  }
}

TEST(ShaderSource, MalformedIncludeMissingVersionAndMissingFileHaveTheirIds) {
  auto idOf = [](const fs::path& file) {
    try {
      assembleShaderSource(file, testing::sharedIncludeDirs());
    } catch (const GpuError& e) {
      return e.id();
    }
    return Diagnostic::GlDebugInfo;  // no error: never expected below
  };
  EXPECT_EQ(idOf(loaderPath("malformed_include.comp")), Diagnostic::IncludeMalformed);
  EXPECT_EQ(idOf(loaderPath("no_version.comp")), Diagnostic::MissingVersion);
  EXPECT_EQ(idOf(loaderPath("not_there.comp")), Diagnostic::ShaderFileNotFound);
  EXPECT_EQ(idOf(loaderPath("lib")), Diagnostic::ShaderFileNotFound);  // a folder
}

// Spacing around '#', trailing comments, CRLF endings; and lookalikes that are not includes.
TEST(ShaderSource, IncludeSyntaxVariants) {
  fs::path dir =
      fs::temp_directory_path() / ("prism_gpu_include_syntax_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
  };
  write("lib.glsl", "float lib() { return 1.0; }\r\n");
  write("root.comp",
        "#version 450\r\n"
        "  #  include   \"lib.glsl\"   // spaced, commented\r\n"
        "#includes_nothing\r\n"
        "// #include \"not_a_directive.glsl\"\r\n"
        "void main() {}\r\n");
  ShaderSource source = assembleShaderSource(dir / "root.comp", {});
  EXPECT_EQ(source.files.size(), 2u);
  EXPECT_NE(source.text.find("float lib()"), std::string::npos);
  EXPECT_NE(source.text.find("#includes_nothing\n"), std::string::npos);
  EXPECT_EQ(source.text.find('\r'), std::string::npos);
  for (const char* bad : {"#include lib.glsl", "#include \"\"", "#include \"lib.glsl\" trailing",
                          "#include \"lib.glsl"}) {
    write("bad.comp", std::string("#version 450\n") + bad + "\n");
    try {
      assembleShaderSource(dir / "bad.comp", {});
      ADD_FAILURE() << bad << " accepted";
    } catch (const GpuError& e) {
      EXPECT_EQ(e.id(), Diagnostic::IncludeMalformed) << bad << ": " << e.what();
      EXPECT_TRUE(std::string(e.what()).starts_with((dir / "bad.comp").string() + ":2: error:"))
          << e.what();
    }
  }
  fs::remove_all(dir);
}

// core/data_files.h's shaderDirectory(), which the GPU tests rely on: $PRISM_SHADER_DIR
// first, else (in a build tree) the source tree's shaders/.
TEST(ShaderDirectory, EnvironmentFirstThenTheSourceTree) {
  const char* saved = std::getenv("PRISM_SHADER_DIR");
  std::string previous = saved ? saved : "";
  ::setenv("PRISM_SHADER_DIR", "/somewhere/else/shaders", 1);
  EXPECT_EQ(shaderDirectory(), fs::path("/somewhere/else/shaders"));
  ::unsetenv("PRISM_SHADER_DIR");
  EXPECT_TRUE(fs::is_regular_file(shaderDirectory() / "shared" / "prelude.glsl"))
      << shaderDirectory();
  EXPECT_TRUE(
      fs::equivalent(shaderDirectory(), testing::testDirectory() / ".." / ".." / "shaders"));
  if (saved) ::setenv("PRISM_SHADER_DIR", previous.c_str(), 1);
}

TEST(ShaderLog, MapsMesaGlslangAndNvidiaFormsToOriginalFiles) {
  std::vector<fs::path> files{"kernel.comp", "shared/cielab.glsl"};
  std::string log =
      "1:12(3): error: `x' undeclared\n"
      "0:4(10): warning: unused\n"
      "ERROR: 1:7: 'y' : undeclared identifier\n"
      "WARNING: 0:2: something\n"
      "1(33) : error C1008: undefined variable \"z\"\n"
      "9:1(1): error: source string 9 is not ours\n"
      "error: linking failed\n";
  EXPECT_EQ(mapShaderLog(log, files),
            "shared/cielab.glsl:12:3: error: `x' undeclared\n"
            "kernel.comp:4:10: warning: unused\n"
            "shared/cielab.glsl:7: error: 'y' : undeclared identifier\n"
            "kernel.comp:2: warning: something\n"
            "shared/cielab.glsl:33: error C1008: undefined variable \"z\"\n"
            "9:1(1): error: source string 9 is not ours\n"
            "error: linking failed\n");
  EXPECT_EQ(firstErrorLine("kernel.comp:4:10: warning: unused\nkernel.comp:5:1: error: bad\n"),
            "kernel.comp:5:1: error: bad");
}

}  // namespace
}  // namespace prism::gpu

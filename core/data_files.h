// Where Prism finds its data/ folder at run time, first match wins:
//   1. $PRISM_DATA_DIR;
//   2. ../share/prism/data beside the running executable (an installed, relocatable prism);
//   3. the package's, in a program built against an installed Prism (setPackageDirectories);
//   4. the source tree this library was built from (developers' builds);
//   5. the data folder of the install prefix configured at build time.
// Never anything outside these. shaderDirectory() finds the installed GLSL (shaders/, holding
// shared/) the same way: $PRISM_SHADER_DIR, ../share/prism/shaders beside the executable, the
// package's, the source tree's shaders/, the install prefix's share/prism/shaders.
// exampleSceneDirectory() finds the example scenes (scenes/) likewise, with $PRISM_SCENE_DIR.
#pragma once

#include <filesystem>
#include <string_view>

namespace prism {

std::filesystem::path dataDirectory();
// Path of a file in data/; Error naming the file and the folder searched when it is missing.
std::filesystem::path dataFile(std::string_view name);

// The folder holding shared/ (the dual-compiled headers) and, later, the GPU passes' shaders.
std::filesystem::path shaderDirectory();

// The example scenes (scenes/*.json and their models), which `prism demo` renders.
std::filesystem::path exampleSceneDirectory();

// The folders of the installed package a program was built against: PrismConfig.cmake compiles a
// call of this into every target that links Prism (prism_package_directories.cpp, run before
// main), since a static library cannot know where it was installed (`cmake --install --prefix`
// moves it after the build) and the consumer's executable does not lie beside it. Without it, a
// consumer read the source tree's data or, with none, the build's configured prefix.
void setPackageDirectories(std::filesystem::path data, std::filesystem::path shaders, std::filesystem::path scenes);

}  // namespace prism

#include "core/data_files.h"

#include <cstdlib>
#include <string>
#include <utility>

#include "core/error.h"

namespace prism {
namespace {

struct PackageDirectories {
  std::filesystem::path data, shaders, scenes;
};

// Set before main by a consumer's package source, read after (a function's static: no order of
// initialisation to rely on).
PackageDirectories& packageDirectories() {
  static PackageDirectories directories;
  return directories;
}

// One lookup order for every run-time folder: the variable, beside the executable, the package's,
// the source tree, the install prefix. shaders/ sits beside data/ both in the source tree and
// under share/prism, so its two build-time locations are derived from data/'s.
std::filesystem::path findDirectory(const char* variable, const char* name, const std::filesystem::path& package,
                                    const std::filesystem::path& source, const std::filesystem::path& installed) {
  if (const char* env = std::getenv(variable); env && *env) return env;
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    std::filesystem::path beside = exe.parent_path().parent_path() / "share" / "prism" / name;
    if (std::filesystem::is_directory(beside, ec)) return beside;
  }
  if (!package.empty() && std::filesystem::is_directory(package, ec)) return package;
  if (std::filesystem::is_directory(source)) return source;
  return installed;
}

}  // namespace

std::filesystem::path dataDirectory() {
  return findDirectory("PRISM_DATA_DIR", "data", packageDirectories().data, PRISM_SOURCE_DATA_DIR,
                       PRISM_INSTALL_DATA_DIR);
}

std::filesystem::path shaderDirectory() {
  return findDirectory("PRISM_SHADER_DIR", "shaders", packageDirectories().shaders,
                       std::filesystem::path(PRISM_SOURCE_DATA_DIR).parent_path() / "shaders",
                       std::filesystem::path(PRISM_INSTALL_DATA_DIR).parent_path() / "shaders");
}

std::filesystem::path exampleSceneDirectory() {
  return findDirectory("PRISM_SCENE_DIR", "scenes", packageDirectories().scenes,
                       std::filesystem::path(PRISM_SOURCE_DATA_DIR).parent_path() / "scenes",
                       std::filesystem::path(PRISM_INSTALL_DATA_DIR).parent_path() / "scenes");
}

void setPackageDirectories(std::filesystem::path data, std::filesystem::path shaders, std::filesystem::path scenes) {
  packageDirectories() = {std::move(data), std::move(shaders), std::move(scenes)};
}

std::filesystem::path dataFile(std::string_view name) {
  std::filesystem::path dir = dataDirectory();
  std::filesystem::path path = dir / name;
  if (!std::filesystem::is_regular_file(path))
    throw Error(path.string() + ": data file not found (data folder " + dir.string() +
                "; set PRISM_DATA_DIR to override)");
  return path;
}

}  // namespace prism

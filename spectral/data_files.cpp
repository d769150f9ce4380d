#include "spectral/data_files.h"

#include <cstdlib>
#include <string>

#include "spectral/error.h"

namespace prism {

std::filesystem::path dataDirectory() {
  if (const char* env = std::getenv("PRISM_DATA_DIR"); env && *env) return env;
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    std::filesystem::path beside = exe.parent_path().parent_path() / "share" / "prism" / "data";
    if (std::filesystem::is_directory(beside, ec)) return beside;
  }
  std::filesystem::path source = PRISM_SOURCE_DATA_DIR;
  if (std::filesystem::is_directory(source)) return source;
  return PRISM_INSTALL_DATA_DIR;
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

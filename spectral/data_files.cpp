#include "spectral/data_files.h"

#include <cstdlib>
#include <string>

#include "spectral/error.h"

namespace prism {

std::filesystem::path dataDirectory() {
  if (const char* env = std::getenv("PRISM_DATA_DIR"); env && *env) return env;
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

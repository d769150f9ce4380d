#include "core/input_file.h"

#include <string>

#include "core/error.h"

namespace prism {

void requireInputFile(const std::filesystem::path& path, std::string_view what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw Error(path.string() + ": cannot open: no such file");
  if (fs::is_directory(status)) throw Error(path.string() + ": is a folder, not " + std::string(what));
  if (fs::is_character_file(status) || fs::is_block_file(status) || fs::is_socket(status))
    throw Error(path.string() + ": not a regular file (a device or a socket), not " + std::string(what));
}

}  // namespace prism

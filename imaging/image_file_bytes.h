// An image file's bytes for stb_image's decoders (PNG, Radiance .hdr), which read from memory
// and take at most 2 GiB. Error "FILE: …" on one line for a folder, a file that cannot be opened
// or read, or one too large.
#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/input_file.h"

namespace prism::imaging {

inline std::string readImageFileBytes(const std::filesystem::path& path) {
  requireInputFile(path, "an image");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open: " + std::strerror(errno));
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw Error(path.string() + ": cannot read: " + std::strerror(errno));
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(path.string() + ": too large for stb_image (over 2 GiB)");
  return bytes;
}

}  // namespace prism::imaging

#include "imaging/radiance_hdr.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace prism::imaging {
namespace {

// The header's lines up to the blank one, then the resolution line (Radiance's file format, as
// in Greg Ward's "Real Pixels"); only the standard orientation, which stb decodes, is accepted.
void checkHeader(const std::string& name, const std::string& bytes) {
  if (!bytes.starts_with("#?RADIANCE\n") && !bytes.starts_with("#?RGBE\n"))
    throw Error(name + ": not a Radiance .hdr file (no #?RADIANCE signature)");
  std::size_t at = bytes.find('\n') + 1;
  for (;;) {
    std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) throw Error(name + ": truncated: the header has no end (a blank line)");
    std::string line = bytes.substr(at, end - at);
    at = end + 1;
    if (line.empty()) break;
    if (line.starts_with("FORMAT=") && line != "FORMAT=32-bit_rle_rgbe")
      throw Error(name + ": " + excerpt(line) + ": Prism reads RGBE only (FORMAT=32-bit_rle_rgbe)");
  }
  std::size_t end = bytes.find('\n', at);
  if (end == std::string::npos) throw Error(name + ": truncated: no resolution line after the header");
  std::string line = bytes.substr(at, end - at);
  std::istringstream in(line);
  std::string ySign, xSign, rest;
  long long height = 0, width = 0;
  if (!(in >> ySign >> height >> xSign >> width) || ySign != "-Y" || xSign != "+X" || (in >> rest))
    throw Error(name + ": resolution line '" + excerpt(line) + "': Prism reads '-Y HEIGHT +X WIDTH' only");
  if (width < 1 || height < 1 || width > kMaxHdrSide || height > kMaxHdrSide) {
    throw Error(name + ": an image of " + std::to_string(width) + " × " + std::to_string(height) +
                " pixels; Prism reads 1 to " + std::to_string(kMaxHdrSide) + " on each side");
  }
  // A run-length encoded scan line (8 or more pixels) takes at least 2 bytes per 127 pixels per
  // component, and 4 bytes of its own; a narrower one is flat, 4 bytes a pixel. Fewer bytes than
  // that cannot hold the image (stb would allocate it first).
  const double lineBytes = width < 8 ? 4.0 * static_cast<double>(width)
                                 : 4.0 + 8.0 * std::ceil(static_cast<double>(width) / 127.0);
  const double needed = static_cast<double>(height) * lineBytes;
  if (static_cast<double>(bytes.size() - end - 1) < needed) {
    throw Error(name + ": truncated: a " + std::to_string(width) + " × " + std::to_string(height) +
                " image needs at least " + std::to_string(static_cast<long long>(needed)) + " bytes of pixels, it has " +
                std::to_string(bytes.size() - end - 1));
  }
}

}  // namespace

FloatImage readRadianceHdr(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) throw Error(path.string() + ": is a folder, not an image");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open: " + std::strerror(errno));
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw Error(path.string() + ": cannot read: " + std::strerror(errno));
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(path.string() + ": too large for stb_image (over 2 GiB)");
  checkHeader(path.string(), bytes);
  int width = 0, height = 0, fileChannels = 0;
  float* pixels = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                         static_cast<int>(bytes.size()), &width, &height, &fileChannels, 3);
  if (!pixels) throw Error(path.string() + ": not a readable .hdr image: " + excerpt(stbi_failure_reason()));
  FloatImage image(width, height, 3);
  std::copy(pixels, pixels + image.pixels.size(), image.pixels.begin());
  stbi_image_free(pixels);
  return image;
}

void writeRadianceHdr(const std::filesystem::path& path, const FloatImage& image) {
  PRISM_CHECK(image.channels >= 3 && image.width > 0 && image.height > 0);
  std::vector<float> rgb;
  rgb.reserve(3 * image.pixelCount());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) rgb.push_back(std::max(image.at(x, y, c), 0.0f));
  std::string bytes;
  auto append = [](void* context, void* chunk, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(chunk), static_cast<std::size_t>(size));
  };
  if (!stbi_write_hdr_to_func(append, &bytes, image.width, image.height, 3, rgb.data()))
    throw Error(path.string() + ": .hdr encoding failed");
  writeFileAtomically(path, bytes);
}

}  // namespace prism::imaging

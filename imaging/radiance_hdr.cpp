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
#include "imaging/image_file_bytes.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace prism::imaging {
namespace {

// The header's lines up to the blank one, then the resolution line (Radiance's file format, as
// in Greg Ward's "Real Pixels"); only the standard orientation, which stb decodes, is accepted.
// A line is read up to its first NUL byte, as stb reads it. Then every scan line is walked as
// stb_image decodes it, so that what it is given holds the whole image: stb reads a missing byte
// as 0 (a zero-length run would never end) and a flat file's missing pixels as garbage, and
// ignores bytes after the image.
void checkHeader(const std::string& name, const std::string& bytes) {
  if (!bytes.starts_with("#?RADIANCE\n") && !bytes.starts_with("#?RGBE\n"))
    throw Error(name + ": not a Radiance .hdr file (no #?RADIANCE signature)");
  std::size_t at = bytes.find('\n') + 1;
  auto nextLine = [&](const char* missing) {
    std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) throw Error(name + ": truncated: " + missing);
    std::string line = bytes.substr(at, end - at);
    at = end + 1;
    return line.substr(0, line.find('\0'));
  };
  bool rgbe = false;
  for (std::string line = nextLine("the header has no end (a blank line)"); !line.empty();
       line = nextLine("the header has no end (a blank line)")) {
    if (!line.starts_with("FORMAT=")) continue;
    if (line != "FORMAT=32-bit_rle_rgbe")
      throw Error(name + ": " + excerpt(line) + ": Prism reads RGBE only (FORMAT=32-bit_rle_rgbe)");
    rgbe = true;
  }
  if (!rgbe) throw Error(name + ": the header has no FORMAT=32-bit_rle_rgbe line");
  std::string line = nextLine("no resolution line after the header");
  std::istringstream in(line);
  std::string ySign, xSign, rest;
  long long height = 0, width = 0;
  if (!(in >> ySign >> height >> xSign >> width) || ySign != "-Y" || xSign != "+X" || (in >> rest))
    throw Error(name + ": resolution line '" + excerpt(line) + "': Prism reads '-Y HEIGHT +X WIDTH' only");
  if (width < 1 || height < 1 || width > kMaxHdrSide || height > kMaxHdrSide) {
    throw Error(name + ": an image of " + std::to_string(width) + " × " + std::to_string(height) +
                " pixels; Prism reads 1 to " + std::to_string(kMaxHdrSide) + " on each side");
  }
  auto byteAt = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  auto truncated = [&](long long y) {
    return Error(name + ": truncated: the data ends in scan line " + std::to_string(y) + " of " +
                 std::to_string(height) + " (" + std::to_string(width) + " × " + std::to_string(height) + ")");
  };
  const auto w = static_cast<std::size_t>(width);
  // stb ignores what follows the image; a file with more (two images joined, a botched copy) is
  // refused, as density files are.
  auto checkNothingAfter = [&](std::size_t end) {
    if (const std::size_t extra = bytes.size() - std::min(end, bytes.size()); extra > 0)
      throw Error(name + ": " + std::to_string(extra) + (extra == 1 ? " byte" : " bytes") + " after the image's last scan line (" +
                  std::to_string(width) + " × " + std::to_string(height) + ")");
  };
  for (long long y = 0; y < height; ++y) {
    // Narrow images, and any scan line without the run-length marker, make stb read the whole
    // image flat, 4 bytes a pixel, from that line's first byte on (from line 0 again, over what
    // the compressed lines before it gave).
    const bool marked = width >= 8 && at + 4 <= bytes.size() && byteAt(at) == 2 && byteAt(at + 1) == 2 &&
                        (byteAt(at + 2) & 0x80) == 0;
    if (!marked) {
      const std::size_t whole = (bytes.size() - at) / (4 * w);  // flat lines
      if (whole >= static_cast<std::size_t>(height)) {
        checkNothingAfter(at + static_cast<std::size_t>(height) * 4 * w);
        return;
      }
      if (y == 0) throw truncated(static_cast<long long>(whole));
      throw Error(name + ": truncated: scan line " + std::to_string(y) + " has no run-length marker, so the whole image "
                  "is read flat from it, and that data ends in its scan line " + std::to_string(whole) + " of " +
                  std::to_string(height) + " (" + std::to_string(width) + " × " + std::to_string(height) + ")");
    }
    if ((static_cast<std::size_t>(byteAt(at + 2)) << 8 | byteAt(at + 3)) != w)
      throw Error(name + ": scan line " + std::to_string(y) + " claims another width than " + std::to_string(width));
    at += 4;
    for (int component = 0; component < 4; ++component) {
      for (std::size_t left = w; left > 0;) {
        if (at >= bytes.size()) throw truncated(y);
        std::size_t count = byteAt(at++);
        const bool run = count > 128;
        if (run) count -= 128;
        if (count == 0 || count > left)
          throw Error(name + ": scan line " + std::to_string(y) + ": a run of " + std::to_string(count) + " pixels where " +
                      std::to_string(left) + " are left");
        at += run ? 1 : count;
        if (at > bytes.size()) throw truncated(y);
        left -= count;
      }
    }
  }
  checkNothingAfter(at);
}

}  // namespace

FloatImage readRadianceHdr(const std::filesystem::path& path) {
  const std::string bytes = readImageFileBytes(path);
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

#include "imaging/png_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <zlib.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "imaging/image_file_bytes.h"
#include "spectral/colour_space.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace prism::imaging {
namespace {

// The display spaces a PNG may be in and their ITU-T H.273 codes (colour primaries, transfer):
// BT.709 with IEC 61966-2-1's curve, SMPTE EG 432-1 (P3, D65) with the same curve, BT.2020 with
// its own (written as code 14; 1 and 15 name the same function).
struct CicpSpace {
  const char* name;
  std::uint8_t primaries, transfer;
};
constexpr CicpSpace kCicpSpaces[] = {{"srgb", 1, 13}, {"display-p3", 12, 13}, {"rec2020", 9, 14}};

std::uint32_t bigEndian32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
         static_cast<std::uint32_t>(p[2]) << 8 | p[3];
}

// The name of the space the PNG's cICP chunk gives ("srgb" without one), found among the chunks
// before the image data; Error naming the file for codes of another space.
std::string cicpColourSpace(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  for (std::size_t at = 8; at + 12 <= bytes.size();) {
    const std::uint32_t length = bigEndian32(&bytes[at]);
    const std::uint8_t* type = &bytes[at + 4];
    if (std::memcmp(type, "IDAT", 4) == 0 || length > bytes.size() - at - 12) break;
    if (std::memcmp(type, "cICP", 4) == 0 && length == 4) {
      const std::uint8_t primaries = bytes[at + 8], transfer = bytes[at + 9];
      for (const CicpSpace& s : kCicpSpaces) {
        const bool sameCurve = transfer == s.transfer || (s.primaries == 9 && (transfer == 1 || transfer == 15));
        if (primaries == s.primaries && sameCurve && bytes[at + 10] == 0 && bytes[at + 11] == 1) return s.name;
      }
      throw Error(fmt::format("{}: cICP names colour primaries {}, transfer {}, matrix {}, full range {}: Prism reads "
                              "sRGB (1, 13), Display P3 (12, 13) and Rec.2020 (9, 14) RGB at full range",
                              path.string(), primaries, transfer, bytes[at + 10], bytes[at + 11]));
    }
    at += 12 + length;
  }
  return "srgb";
}

}  // namespace

void PngImage::setColourSpace(const std::string& name) {
  const std::string& canonical = prism::colourSpace(name).name;  // "p3" is "display-p3"
  for (const CicpSpace& s : kCicpSpaces)
    if (canonical == s.name) {
      mColourSpace = canonical;
      return;
    }
  throw Error(fmt::format("{}: no display encodes it; a PNG is in srgb, display-p3 or rec2020", name));
}

PngImage::PngImage(int width, int height, Rgb8 background)
    : mWidth(width),
      mHeight(height),
      mRgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
  PRISM_CHECK(width >= 0 && height >= 0);
  fillRect(0, 0, width, height, background);
}

Rgb8 PngImage::pixel(int x, int y) const {
  PRISM_CHECK(x >= 0 && y >= 0 && x < mWidth && y < mHeight);  // out of range read another row or past the end
  std::size_t i = index(x, y);
  return {mRgba[i], mRgba[i + 1], mRgba[i + 2]};
}

std::uint8_t PngImage::alpha(int x, int y) const {
  PRISM_CHECK(x >= 0 && y >= 0 && x < mWidth && y < mHeight);
  return mRgba[index(x, y) + 3];
}

void PngImage::setPixel(int x, int y, Rgb8 colour, std::uint8_t alpha) {
  PRISM_CHECK(x >= 0 && y >= 0 && x < mWidth && y < mHeight);
  std::size_t i = index(x, y);
  mRgba[i] = colour.r;
  mRgba[i + 1] = colour.g;
  mRgba[i + 2] = colour.b;
  mRgba[i + 3] = alpha;
}

void PngImage::fillRect(int x, int y, int w, int h, Rgb8 colour) {
  int x0 = std::max(x, 0), y0 = std::max(y, 0);
  int x1 = std::min(x + w, mWidth), y1 = std::min(y + h, mHeight);
  for (int py = y0; py < y1; ++py)
    for (int px = x0; px < x1; ++px) setPixel(px, py, colour);
}

void PngImage::drawText(int x, int y, std::string_view text, Rgb8 colour, int scale) {
  // stb_easy_font emits axis-aligned quads (4 vertices of x, y, z, rgba) in font pixels.
  struct Vertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  std::string copy(text);
  std::vector<Vertex> quads(copy.size() * 80);
  int count = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, quads.data(),
                                  static_cast<int>(quads.size() * sizeof(Vertex)));
  for (int q = 0; q < count; ++q) {
    const Vertex* v = &quads[static_cast<std::size_t>(q) * 4];
    int qx = static_cast<int>(v[0].x), qy = static_cast<int>(v[0].y);
    int qw = static_cast<int>(v[2].x) - qx, qh = static_cast<int>(v[2].y) - qy;
    fillRect(x + qx * scale, y + qy * scale, qw * scale, qh * scale, colour);
  }
}

int textWidth(std::string_view text, int scale) {
  std::string copy(text);
  return stb_easy_font_width(copy.data()) * scale;
}

void PngImage::write(const std::filesystem::path& path) const {
  bool opaque = true;
  for (std::size_t i = 3; i < mRgba.size() && opaque; i += 4) opaque = mRgba[i] == 255;
  std::vector<std::uint8_t> rgb;
  const std::uint8_t* data = mRgba.data();
  int components = 4;
  if (opaque) {
    rgb.reserve(mRgba.size() / 4 * 3);
    for (std::size_t i = 0; i < mRgba.size(); i += 4) rgb.insert(rgb.end(), &mRgba[i], &mRgba[i + 3]);
    data = rgb.data();
    components = 3;
  }
  std::string bytes;
  auto append = [](void* context, void* chunk, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(chunk),
                                               static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, mWidth, mHeight, components, data, mWidth * components))
    throw Error(path.string() + ": PNG encoding failed");
  // cICP after IHDR (8-byte signature, IHDR's 25 bytes): primaries, transfer, matrix 0 (RGB), full range.
  for (const CicpSpace& s : kCicpSpaces)
    if (mColourSpace == s.name) {
      const std::uint8_t typeAndData[8] = {'c', 'I', 'C', 'P', s.primaries, s.transfer, 0, 1};
      const auto crc = static_cast<std::uint32_t>(crc32(0L, typeAndData, sizeof typeAndData));
      std::string chunk = {'\0', '\0', '\0', '\4'};
      chunk.append(reinterpret_cast<const char*>(typeAndData), sizeof typeAndData);
      for (int shift = 24; shift >= 0; shift -= 8) chunk.push_back(static_cast<char>((crc >> shift) & 0xFF));
      bytes.insert(33, chunk);
    }
  writeFileAtomically(path, bytes);
}

void checkJpegBeforeDecoding(const std::string& name, std::span<const std::uint8_t> bytes) {
  int width = 0, height = 0, components = 0;
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      !stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &components))
    throw Error(name + ": not a readable JPEG (" + (stbi_failure_reason() ? stbi_failure_reason() : "no header") + ")");
  if (width < 1 || height < 1 || width > kMaxPngSide || height > kMaxPngSide) {
    throw Error(name + ": an image of " + std::to_string(width) + " × " + std::to_string(height) +
                " pixels; Prism reads 1 to " + std::to_string(kMaxPngSide) + " on each side");
  }
}

void checkPngBeforeDecoding(const std::string& name, std::span<const std::uint8_t> bytes) {
  const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin()))
    throw Error(name + ": not a PNG file (no PNG signature)");
  // The first chunk is IHDR: width and height, big-endian (PNG specification, §11.2.2).
  const std::uint8_t ihdr[4] = {'I', 'H', 'D', 'R'};
  if (bytes.size() < 24 || !std::equal(ihdr, ihdr + 4, bytes.begin() + 12))
    throw Error(name + ": not a readable image: no IHDR chunk first");
  auto bigEndian = [&](std::size_t at) {
    return static_cast<std::uint32_t>(bytes[at]) << 24 | static_cast<std::uint32_t>(bytes[at + 1]) << 16 |
           static_cast<std::uint32_t>(bytes[at + 2]) << 8 | bytes[at + 3];
  };
  const std::uint32_t width = bigEndian(16), height = bigEndian(20);
  if (width < 1 || height < 1 || width > kMaxPngSide || height > kMaxPngSide) {
    throw Error(name + ": an image of " + std::to_string(width) + " × " + std::to_string(height) +
                " pixels; Prism reads 1 to " + std::to_string(kMaxPngSide) + " on each side");
  }
  // Deflate packs at most 1032 bytes into one: fewer bytes than a byte a pixel over 1032 cannot
  // hold the image, however uniform (stb would allocate all of it before finding that out).
  const double needed = static_cast<double>(width) * static_cast<double>(height) / 1032.0;
  if (static_cast<double>(bytes.size()) < needed) {
    throw Error(name + ": truncated: a " + std::to_string(width) + " × " + std::to_string(height) +
                " PNG needs at least " + std::to_string(static_cast<long long>(needed)) + " bytes, it has " +
                std::to_string(bytes.size()));
  }
}

std::string stbDecodeFailure() {
  const char* reason = stbi_failure_reason();
  if (!reason) return "stb gave no reason";
  const std::string_view r(reason);
  // stb's reason may quote the file's bytes (an unknown chunk's type).
  if (r == "outofdata" || r == "no IDAT" || r == "bad EOF") return "its data ends early (truncated; stb: " + excerpt(reason) + ")";
  if (r.starts_with("bad huffman") || r.starts_with("bad zlib") || r.starts_with("bad codelengths") || r.starts_with("bad dist") ||
      r.starts_with("read past buffer") || r == "not enough pixels" || r == "Corrupt PNG")
    return "a damaged compressed stream (stb: " + excerpt(reason) + ")";
  // A chunk type stb does not know, or part of one where the file ends inside it ("IDA").
  if (r.ends_with("PNG chunk not known") || r.size() < 4) return "a damaged or truncated chunk (stb: " + excerpt(reason) + ")";
  return "stb: " + excerpt(reason);
}

PngImage readPng8(const std::filesystem::path& path) {
  const std::string bytes = readImageFileBytes(path);
  checkPngBeforeDecoding(path.string(), {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
  int width = 0, height = 0, fileChannels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          static_cast<int>(bytes.size()), &width, &height, &fileChannels, 4);
  // stb's reason may quote the file's bytes (an unknown chunk's type).
  if (!pixels) throw Error(path.string() + ": cannot decode the PNG: " + stbDecodeFailure());
  const std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> owned(pixels, &stbi_image_free);
  PngImage image;
  image.mColourSpace = cicpColourSpace(path, {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
  image.mWidth = width;
  image.mHeight = height;
  image.mRgba.assign(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  return image;
}

}  // namespace prism::imaging

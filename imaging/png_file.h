// 8-bit display-encoded images as PNG files: reading (stb_image), writing atomically
// (stb_image_write), and simple drawing for charts, legends and galleries (rectangles, and
// ASCII text in the stb_easy_font face). The stb implementations come compiled in Debian's
// libstb, so no file here defines STB_*_IMPLEMENTATION. An image is sRGB unless it says it is
// Display P3 or Rec.2020: a written PNG carries its colour space in a cICP chunk (PNG third
// edition; ITU-T H.273 codes), which viewers and `prism compare` read — an untagged P3 or
// Rec.2020 file is shown as sRGB everywhere.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace prism::imaging {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(Rgb8, Rgb8) = default;
};

// RGBA, 4 bytes a pixel, row 0 at the top; alpha is straight (not premultiplied).
class PngImage {
 public:
  PngImage() = default;  // 0 × 0
  // Opaque, filled with `background`.
  PngImage(int width, int height, Rgb8 background);

  int width() const { return mWidth; }
  int height() const { return mHeight; }
  Rgb8 pixel(int x, int y) const;
  std::uint8_t alpha(int x, int y) const;
  void setPixel(int x, int y, Rgb8 colour, std::uint8_t alpha = 255);
  // Fills [x, x+w) × [y, y+h), clipped to the image, opaque.
  void fillRect(int x, int y, int w, int h, Rgb8 colour);
  // ASCII text in the stb_easy_font face, each font pixel drawn as scale × scale; (x, y) is the
  // top left of the first character.
  void drawText(int x, int y, std::string_view text, Rgb8 colour, int scale);
  // RGB when every pixel is opaque, RGBA otherwise. Error naming the path when it fails; a
  // failed write leaves no file behind (core/atomic_file.h).
  void write(const std::filesystem::path& path) const;

  const std::vector<std::uint8_t>& rgba() const { return mRgba; }

  // The colour space its bytes encode: "srgb" (the default, and a file without cICP),
  // "display-p3" or "rec2020" (spectral/colour_space.h's names). Error for any other: no display
  // encodes it.
  const std::string& colourSpace() const { return mColourSpace; }
  void setColourSpace(const std::string& name);

 private:
  friend PngImage readPng8(const std::filesystem::path& path);
  std::size_t index(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(mWidth) + static_cast<std::size_t>(x)) * 4;
  }

  int mWidth = 0, mHeight = 0;
  std::vector<std::uint8_t> mRgba;
  std::string mColourSpace = "srgb";
};

// Width in pixels of `text` drawn by PngImage::drawText at `scale` (its widest line).
int textWidth(std::string_view text, int scale);

// A PNG of any bit depth (stb_image) as 8-bit RGBA; grey and RGB files come back opaque, with the
// colour space its cICP chunk names (sRGB without one). Error naming the file when it is missing,
// not a PNG (stb's other formats, TGA above all, have no signature: any 17 bytes may claim a huge
// TGA), fails checkPngBeforeDecoding, or its cICP names a space Prism does not decode.
PngImage readPng8(const std::filesystem::path& path);

// The largest side Prism decodes (what `prism render` can write: its --width/--height limit).
inline constexpr int kMaxPngSide = 16384;

// Before a PNG is decoded: its signature, its size from the header (1 to kMaxPngSide a side), and
// enough bytes to hold that many pixels. Error "NAME: …" otherwise, so that a 17-byte file cannot
// make the decoder allocate gigabytes. readPng8 and the glTF textures' decoder check with it.
void checkPngBeforeDecoding(const std::string& name, std::span<const std::uint8_t> bytes);

// Before a JPEG (a glTF's texture) is decoded: its size from its header as stb_image reads it, 1 to
// kMaxPngSide a side. Error "NAME: …" otherwise: a header claiming 65 000² pixels went to the
// decoder, which would allocate its 17 GB of RGBA before anything looked at its size.
void checkJpegBeforeDecoding(const std::string& name, std::span<const std::uint8_t> bytes);

// Why stb_image's last decode on this thread failed, in words: "its data ends early (truncated)"
// for stb's "outofdata", "a damaged compressed stream (stb: bad huffman code)" for zlib's
// errors, "a damaged or truncated chunk" for a chunk type it does not know (or the few letters
// of one where the file ends), "stb: REASON" otherwise. Every decode goes through stb, tinygltf's too, whose own
// message ("Unknown image format. STB cannot decode image data for image[0] name = \"\"") named a
// PNG's truncation as an unknown format.
std::string stbDecodeFailure();

}  // namespace prism::imaging

// An 8-bit sRGB image for charts and galleries, written as PNG atomically.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace prism::app {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
};

class PngImage {
 public:
  PngImage(int width, int height, Rgb8 background);

  int width() const { return mWidth; }
  int height() const { return mHeight; }
  Rgb8 pixel(int x, int y) const;
  // Fills [x, x+w) × [y, y+h), clipped to the image.
  void fillRect(int x, int y, int w, int h, Rgb8 colour);
  // ASCII text in the stb_easy_font face, each font pixel drawn as scale × scale.
  void drawText(int x, int y, std::string_view text, Rgb8 colour, int scale);
  void write(const std::filesystem::path& path) const;

 private:
  int mWidth, mHeight;
  std::vector<std::uint8_t> mRgb;
};

}  // namespace prism::app

#include "app/png_image.h"

#include <algorithm>
#include <string>

#include "spectral/atomic_file.h"
#include "spectral/error.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop
#include <stb/stb_image_write.h>

namespace prism::app {

PngImage::PngImage(int width, int height, Rgb8 background)
    : mWidth(width), mHeight(height), mRgb(static_cast<std::size_t>(width * height) * 3) {
  fillRect(0, 0, width, height, background);
}

Rgb8 PngImage::pixel(int x, int y) const {
  std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(mWidth) + static_cast<std::size_t>(x)) * 3;
  return {mRgb[i], mRgb[i + 1], mRgb[i + 2]};
}

void PngImage::fillRect(int x, int y, int w, int h, Rgb8 colour) {
  int x0 = std::max(x, 0), y0 = std::max(y, 0);
  int x1 = std::min(x + w, mWidth), y1 = std::min(y + h, mHeight);
  for (int py = y0; py < y1; ++py)
    for (int px = x0; px < x1; ++px) {
      std::size_t i = (static_cast<std::size_t>(py) * static_cast<std::size_t>(mWidth) + static_cast<std::size_t>(px)) * 3;
      mRgb[i] = colour.r;
      mRgb[i + 1] = colour.g;
      mRgb[i + 2] = colour.b;
    }
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

void PngImage::write(const std::filesystem::path& path) const {
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, mWidth, mHeight, 3, mRgb.data(), mWidth * 3))
    throw Error(path.string() + ": PNG encoding failed");
  writeFileAtomically(path, bytes);
}

}  // namespace prism::app

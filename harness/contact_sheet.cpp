#include "harness/contact_sheet.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "render/shared_shading.h"

namespace prism::harness {
namespace {

// The 256 codes' linear values, decoded once.
const std::array<float, 256>& decodedCodes() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = shared::srgbDecode(static_cast<float>(i) / 255.0f);
    return t;
  }();
  return table;
}

std::uint8_t encode(float linear) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(shared::srgbEncode(linear), 0.0f, 1.0f) * 255.0f));
}

// The source pixels [first, last) that output pixel i of n covers, over a side of `size`.
std::pair<int, int> footprint(int i, int n, int size) {
  const int first = static_cast<int>(static_cast<long>(i) * size / n);
  const int last = static_cast<int>(static_cast<long>(i + 1) * size / n);
  return {first, std::max(last, first + 1)};
}

}  // namespace

imaging::PngImage shrinkSrgb(const imaging::PngImage& image, int width, int height) {
  PRISM_CHECK(width >= 1 && height >= 1 && width <= image.width() && height <= image.height());
  const std::array<float, 256>& linear = decodedCodes();
  imaging::PngImage out(width, height, {0, 0, 0});
  for (int y = 0; y < height; ++y) {
    const auto [y0, y1] = footprint(y, height, image.height());
    for (int x = 0; x < width; ++x) {
      const auto [x0, x1] = footprint(x, width, image.width());
      float r = 0.0f, g = 0.0f, b = 0.0f;
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx) {
          const imaging::Rgb8 p = image.pixel(sx, sy);
          r += linear[p.r];
          g += linear[p.g];
          b += linear[p.b];
        }
      const float n = static_cast<float>((x1 - x0) * (y1 - y0));
      out.setPixel(x, y, {encode(r / n), encode(g / n), encode(b / n)});
    }
  }
  return out;
}

imaging::PngImage contactSheet(std::span<const SheetCell> cells, const SheetLayout& layout) {
  if (layout.columns < 1 || layout.columns > 64 || layout.cellWidth < 16 || layout.cellWidth > 4096 ||
      layout.cellHeight < 16 || layout.cellHeight > 4096)
    throw Error(fmt::format("contact sheet: {} columns of {}×{} cells is outside 1–64 columns of 16–4096 pixels a side",
                            layout.columns, layout.cellWidth, layout.cellHeight));
  const int count = static_cast<int>(cells.size());
  const int columns = std::min(layout.columns, std::max(count, 1));
  const int rows = (count + columns - 1) / columns;
  imaging::PngImage sheet(columns * layout.cellWidth, std::max(rows, 1) * layout.cellHeight, {0, 0, 0});
  for (int i = 0; i < count; ++i) {
    const SheetCell& cell = cells[static_cast<std::size_t>(i)];
    if (cell.image->colourSpace() != "srgb")
      throw Error(fmt::format("contact sheet: {} is encoded for {}, the sheet for sRGB", cell.label,
                              cell.image->colourSpace()));
    const double scale = std::min({1.0, static_cast<double>(layout.cellWidth) / cell.image->width(),
                                   static_cast<double>(layout.cellHeight) / cell.image->height()});
    const int w = std::max(1, static_cast<int>(std::lround(cell.image->width() * scale)));
    const int h = std::max(1, static_cast<int>(std::lround(cell.image->height() * scale)));
    const imaging::PngImage small = shrinkSrgb(*cell.image, std::min(w, cell.image->width()), std::min(h, cell.image->height()));
    const int left = (i % columns) * layout.cellWidth, top = (i / columns) * layout.cellHeight;
    const int ox = left + (layout.cellWidth - small.width()) / 2, oy = top + (layout.cellHeight - small.height()) / 2;
    for (int y = 0; y < small.height(); ++y)
      for (int x = 0; x < small.width(); ++x) sheet.setPixel(ox + x, oy + y, small.pixel(x, y));
    // The name on a dark strip, legible over any render.
    constexpr int kScale = 2, kStrip = 18;
    sheet.fillRect(left, top, std::min(layout.cellWidth, 8 + imaging::textWidth(cell.label, kScale)), kStrip, {0, 0, 0});
    sheet.drawText(left + 4, top + 3, cell.label, {255, 255, 255}, kScale);
  }
  return sheet;
}

}  // namespace prism::harness

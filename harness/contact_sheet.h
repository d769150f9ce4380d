// One image of a whole gallery: each image shrunk into a cell of a grid, its name written over
// it, so that `prism demo`'s renders can be seen (and shown: the README's docs/gallery.png) at
// once. Shrinking averages in linear light (sRGB decoded and encoded again by
// shaders/shared/transfer.glsl), so that a fine pattern keeps its brightness.
#pragma once

#include <span>
#include <string>

#include "imaging/png_file.h"

namespace prism::harness {

struct SheetCell {
  const imaging::PngImage* image = nullptr;  // sRGB, opaque
  std::string label;
};

struct SheetLayout {
  int columns = 4;
  int cellWidth = 320;
  int cellHeight = 180;
};

// The cells in rows of `columns`, each image fitted within its cell (aspect kept, centred on
// black, never enlarged) and labelled at its top left. Error for an image that is not sRGB, or a
// layout outside 1–64 columns and 16–4096 pixels a cell side.
imaging::PngImage contactSheet(std::span<const SheetCell> cells, const SheetLayout& layout);

// `image` shrunk to width × height (each at most the image's) by the mean of the pixels each
// output pixel covers, in linear light.
imaging::PngImage shrinkSrgb(const imaging::PngImage& image, int width, int height);

}  // namespace prism::harness

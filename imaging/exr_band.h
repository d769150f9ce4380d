// EXR files that hold a band of rows of a larger image as named float channels, with string
// attributes: the parts of work split across processes (batch/reference_part.h), which carry
// more than a colour (a mean's rounding residual, a variance) and say which rows of which image
// they are. The band is the file's data window inside its display window, as OpenEXR means them,
// so any EXR viewer places it; `prism compare` and readExr (exr_file.h) read its colour channels.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace prism::imaging {

struct ExrBand {
  int width = 0, height = 0;    // the whole image (display window)
  int rowBegin = 0, rows = 0;   // the rows held (data window), full width
  std::map<std::string, std::string> attributes;  // string attributes, by name
  std::vector<std::string> channels;              // channel names
  std::vector<std::vector<float>> planes;         // per channel: rows × width, row-major
};

// ZIP-compressed float scan lines, written atomically (core/atomic_file.h). PRISM_CHECKs that the
// band is inside the image and that each plane has rows × width values.
void writeExrBand(const std::filesystem::path& path, const ExrBand& band);

// The band's windows, attributes (string ones; others are skipped) and channel names; with
// `pixels`, also every channel as float (`planes`). Error naming the file, on one line, when it
// is not an EXR, is damaged or truncated (with `pixels`, a part whose pixels cannot all be read),
// or its data window is not full-width rows inside its display window.
ExrBand readExrBand(const std::filesystem::path& path, bool pixels);

}  // namespace prism::imaging

// Radiance RGBE files (.hdr), the other format HDR environment maps are published in: read with
// stb_image's decoder and written with stb_image_write (both compiled in Debian's libstb). The
// format names no primaries; Prism reads its RGB as linear sRGB (Rec. 709, D65), as the maps
// published for rendering are made.
#pragma once

#include <filesystem>

#include "imaging/float_image.h"

namespace prism::imaging {

// The largest side readRadianceHdr takes: 16K environment maps are the largest published.
inline constexpr int kMaxHdrSide = 16384;

// Three channels, row 0 at the top. The file is checked before anything is decoded — the
// "#?RADIANCE" (or "#?RGBE") signature, a FORMAT=32-bit_rle_rgbe line, a standard "-Y H +X W"
// resolution line with sides of 1 to kMaxHdrSide, and scan lines that hold every pixel (each
// run-length encoded line walked as the decoder will read it). Error "FILE: …" on one line
// otherwise.
FloatImage readRadianceHdr(const std::filesystem::path& path);

// RGB (alpha dropped), run-length encoded, atomically (core/atomic_file.h); negative values are
// written as 0, which RGBE cannot hold. Error naming the path when it fails.
void writeRadianceHdr(const std::filesystem::path& path, const FloatImage& image);

}  // namespace prism::imaging

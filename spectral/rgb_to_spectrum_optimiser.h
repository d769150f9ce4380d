// Building a Jakob–Hanika table with Prism's own optimiser (never copied from elsewhere).
//
// Every node's coefficients come from SigmoidFitter (Levenberg–Marquardt, analytic Jacobian,
// CIE76 in CIELAB under the gamut's white illuminant and CIE 1931). As in Jakob & Hanika 2019
// §4, each (block, x, y) column starts at a dim, stable colour (k = res/5) from zero
// coefficients and marches up, then down, the brightness axis, each fit seeded with its
// neighbour's solution. Columns are independent, so threads share them out, and tasks of a
// cluster too (rgb_to_spectrum_part.h); the output depends on neither.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "core/task_split.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism {

// The coarsest table built: each column's march starts at brightness node res/5, which below 5
// nodes is node 0, black, where the fit has nothing to hold on to (a 4³ table missed its nodes by
// an RMS ΔE00 of 32). Files of 2–4 nodes still read.
inline constexpr int kMinBuiltTableResolution = 5;
inline constexpr int kMaxBuiltTableResolution = 256;

struct TableBuildOptions {
  std::string gamut = "srgb";  // a colour space name
  int resolution = 64;         // kMinBuiltTableResolution–kMaxBuiltTableResolution
  unsigned threads = 0;  // 0: all hardware threads
  // Called from the building threads, serialised, with (columns done, columns in all).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

// Error "upsampling table resolution must be within 5–256, got N" otherwise.
void requireBuildableResolution(int resolution);

// The table's columns: (block, y, x), numbered block·res² + y·res + x.
int tableColumns(int resolution);

RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options);
// Only `columns` (a part, rgb_to_spectrum_part.h); the others stay zero.
RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options, IndexRange columns);

}  // namespace prism

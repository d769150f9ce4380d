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

struct TableBuildOptions {
  std::string gamut = "srgb";  // a colour space name
  int resolution = 64;
  unsigned threads = 0;  // 0: all hardware threads
  // Called from the building threads, serialised, with (columns done, columns in all).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

// The table's columns: (block, y, x), numbered block·res² + y·res + x.
int tableColumns(int resolution);

RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options);
// Only `columns` (a part, rgb_to_spectrum_part.h); the others stay zero.
RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options, IndexRange columns);

}  // namespace prism

// Building a Jakob–Hanika table with Prism's own optimiser (never copied from elsewhere).
//
// Every node's coefficients come from SigmoidFitter (Levenberg–Marquardt, analytic Jacobian,
// CIE76 in CIELAB under the gamut's white illuminant and CIE 1931). As in Jakob & Hanika 2019
// §4, each (block, x, y) column starts at a dim, stable colour (k = res/5) from zero
// coefficients and marches up, then down, the brightness axis, each fit seeded with its
// neighbour's solution. Columns are independent, so threads share them out; the output does not
// depend on the thread count.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "spectral/rgb_to_spectrum_table.h"

namespace prism {

struct TableBuildOptions {
  std::string gamut = "srgb";  // a colour space name
  int resolution = 64;
  unsigned threads = 0;  // 0: all hardware threads
  // Called from the building threads, serialised, with (columns done, columns in all).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options);

}  // namespace prism

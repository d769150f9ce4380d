// The small sRGB tables tests use where the arithmetic under test does not depend on the
// resolution (quality is tested at 64³ in rgb_to_spectrum_quality_test.cpp). Each is made once
// per process.
#pragma once

#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

namespace prism {

// 12³, built in the process (two threads): the spectral layer's own tests of a table's layout,
// format and lookups.
inline const RgbToSpectrumTable& smallSrgbTable() {
  static const RgbToSpectrumTable table = buildRgbToSpectrumTable({"srgb", 12, 2, {}});
  return table;
}

// 16³, read from the tests' cache, where the srgb_table fixture (tests/CMakeLists.txt) builds it
// once for every test process above the spectral layer.
inline const RgbToSpectrumTable& cachedTestTable() {
  static const RgbToSpectrumTable table = cachedRgbToSpectrumTable("srgb", 16);
  return table;
}

}  // namespace prism

// `prism lut` (build an upsampling table; with --part I/N only task I of N's share of its columns,
// for `prism merge`: spectral/rgb_to_spectrum_part.h) and `prism upsample` (one colour →
// coefficients and spectrum), for people (text) and scripts (--json).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::app {

struct LutOptions {
  std::string gamut = "srgb";
  int resolution = kRendererTableResolution;
  std::string output;
  unsigned threads = 0;
  bool report = false;  // node and round-trip quality after building
  bool json = false;
  std::string part;     // "I/N": only task I of N's columns, as a part (skipped when already there)
};
void runLut(const LutOptions& options);

// The table's options are unset unless given: --method box uses no table (its bands ignore the
// gamut), and the unbounded intent looks its scaled albedo up one way only, so they refuse them.
struct UpsampleOptions {
  std::vector<double> rgb;
  std::optional<std::string> gamut;                    // unset: srgb
  std::optional<int> resolution;                       // unset: kRendererTableResolution
  std::vector<double> wavelengths{360.0, 830.0, 5.0};  // min, max, step in nm
  std::string intent = "albedo";                       // albedo | unbounded
  std::optional<std::string> path;                     // manual | filtered; unset: manual
  std::string method = "jakob-hanika";                 // jakob-hanika | box (naive)
  bool json = false;
};
void runUpsample(const UpsampleOptions& options);

}  // namespace prism::app

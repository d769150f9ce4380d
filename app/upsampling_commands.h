// `prism lut` (build an upsampling table; with --part I/N only task I of N's share of its columns,
// for `prism merge`: spectral/rgb_to_spectrum_part.h) and `prism upsample` (one colour →
// coefficients and spectrum), for people (text) and scripts (--json).
#pragma once

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

struct UpsampleOptions {
  std::vector<double> rgb;
  std::string gamut = "srgb";
  int resolution = kRendererTableResolution;
  std::vector<double> wavelengths{360.0, 830.0, 5.0};  // min, max, step in nm
  std::string intent = "albedo";                       // albedo | unbounded
  std::string path = "manual";                         // manual | filtered
  std::string method = "jakob-hanika";                 // jakob-hanika | box (naive)
  bool json = false;
};
void runUpsample(const UpsampleOptions& options);

}  // namespace prism::app

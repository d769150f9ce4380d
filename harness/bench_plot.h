// The plot of `prism bench`: frame time against the wavelength count as an SVG, the spectral
// configurations as points with their rounds' range as a bar, the fitted line (for two counts or
// more) and RGB's time as a dashed line.
#pragma once

#include <string>
#include <vector>

#include "harness/bench_statistics.h"

namespace prism::harness {

struct BenchPoint {
  int wavelengths = 0;
  double frameMs = 0.0;     // median over the rounds
  double minFrameMs = 0.0;  // the fastest and slowest round
  double maxFrameMs = 0.0;
};
std::string benchPlotSvg(const std::vector<BenchPoint>& spectral, double rgbMs, const LinearFit& fit,
                         const std::string& title);

}  // namespace prism::harness

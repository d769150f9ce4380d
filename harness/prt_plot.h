// The plot of `prism prt report --plot`: spectral PRT's colour error against the basis size m
// (mean and max ΔE94 and ΔE00 over the object's vertices, log scale), RGB-PRT's as dashed
// lines, and the bound (max ΔE94 = 1) as a grey line: an SVG by log_plot.h.
#pragma once

#include <string>
#include <vector>

namespace prism::harness {

struct BasisSweepPoint {
  int m = 0;  // 0 for RGB-PRT
  double mean94 = 0.0, max94 = 0.0, mean2000 = 0.0, max2000 = 0.0;
};

std::string basisSweepPlotSvg(const std::vector<BasisSweepPoint>& spectral, const BasisSweepPoint& rgb, double bound,
                              const std::string& title);

}  // namespace prism::harness

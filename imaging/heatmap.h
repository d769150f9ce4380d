// Pictures of a ΔE map: a heat map with a legend, and a histogram.
//
// The colour scale is fixed so that heat maps from different runs read alike: five stops of
// matplotlib's "inferno" (van der Walt & Smith 2015), evenly spaced over [0, maxDeltaE] and
// interpolated linearly in sRGB-encoded 8-bit values:
//   0 → #000004 (black), ¼ → #57106E, ½ → #BC3754, ¾ → #F98E09, ≥ max → #FCFFA4 (pale yellow).
// It is monotonic in lightness, so it survives greyscale printing and most colour blindness.
// A pixel whose ΔE is NaN is drawn magenta (#FF00FF), which the scale never uses.
#pragma once

#include "imaging/float_image.h"
#include "imaging/png_file.h"

namespace prism::imaging {

inline constexpr Rgb8 kHeatNaN{255, 0, 255};

// The scale above; negative ΔE is clamped to 0.
Rgb8 heatColour(double deltaE, double maxDeltaE);

struct HeatMapOptions {
  double maxDeltaE = 10.0;  // the top of the scale; anything at or above it is the top colour
  bool legend = true;       // a strip below the map: the scale left to right, ticks, labels
};
// The legend strip's height in pixels (the output is this much taller than the map).
inline constexpr int kHeatLegendHeight = 28;

// `deltaE` has 1 channel (ImageDifference::deltaEMap). Output: the same width; the same height
// plus kHeatLegendHeight with a legend. Labels (0, max/2, ≥max) appear when the map is at least
// 96 pixels wide.
PngImage heatMap(const FloatImage& deltaE, const HeatMapOptions& options = {});

struct HistogramOptions {
  double maxDeltaE = 10.0;  // bins cover [0, maxDeltaE); one more bar at the right counts ≥ max
  int bins = 40;
  int width = 512, height = 256;  // of the whole picture, axes and labels included
};
// Bars in the heat-map colour of their bin's centre, their height linear in the count with the
// fullest bin at full height; x-axis ticks at each whole ΔE (every 5 or 10 past 20 or 50),
// labelled at 0, max/2 and max; the largest count labelled on the y axis.
PngImage deltaEHistogram(const FloatImage& deltaE, const HistogramOptions& options = {});

}  // namespace prism::imaging

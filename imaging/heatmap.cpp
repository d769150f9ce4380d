#include "imaging/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"

namespace prism::imaging {
namespace {

// matplotlib's inferno at 0, ¼, ½, ¾ and 1: entries 0, 64, 128, 192 and 255 of its 256-entry
// table (_cm_listed.py), ×255 and rounded.
constexpr std::array<Rgb8, 5> kStops = {{
    {0x00, 0x00, 0x04},
    {0x57, 0x10, 0x6E},
    {0xBC, 0x37, 0x54},
    {0xF9, 0x8E, 0x09},
    {0xFC, 0xFF, 0xA4},
}};

// Mid grey, so that both ends of the scale (black and pale yellow) stand out against it.
constexpr Rgb8 kBackground{88, 88, 88};
constexpr Rgb8 kInk{240, 240, 240};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

Rgb8 heatColour(double deltaE, double maxDeltaE) {
  if (std::isnan(deltaE)) return kHeatNaN;
  PRISM_CHECK(maxDeltaE > 0.0);
  double t = std::clamp(deltaE / maxDeltaE, 0.0, 1.0) * static_cast<double>(kStops.size() - 1);
  std::size_t i = std::min(static_cast<std::size_t>(t), kStops.size() - 2);
  double f = t - static_cast<double>(i);
  auto mix = [f](std::uint8_t lo, std::uint8_t hi) {
    return static_cast<std::uint8_t>(std::lround(lo + f * (hi - lo)));
  };
  const Rgb8 &lo = kStops[i], &hi = kStops[i + 1];
  return {mix(lo.r, hi.r), mix(lo.g, hi.g), mix(lo.b, hi.b)};
}

PngImage heatMap(const FloatImage& deltaE, const HeatMapOptions& options) {
  PRISM_CHECK(deltaE.channels == 1);
  const int width = deltaE.width, height = deltaE.height;
  PngImage out(width, height + (options.legend ? kHeatLegendHeight : 0), kBackground);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) out.setPixel(x, y, heatColour(deltaE.at(x, y, 0), options.maxDeltaE));
  if (!options.legend || width == 0) return out;

  // The scale from 0 at the left edge to max at the right, then ticks and labels under it.
  const int barTop = height + 3, barHeight = 8, tickBottom = barTop + barHeight + 3;
  for (int x = 0; x < width; ++x) {
    double value = width > 1 ? options.maxDeltaE * x / (width - 1) : 0.0;
    out.fillRect(x, barTop, 1, barHeight, heatColour(value, options.maxDeltaE));
  }
  const std::array<int, 3> tickX = {0, (width - 1) / 2, width - 1};
  for (int x : tickX) out.fillRect(x, barTop + barHeight, 1, tickBottom - barTop - barHeight, kInk);
  if (width >= 96) {
    const std::array<std::string, 3> labels = {"0", number(options.maxDeltaE / 2),
                                               ">=" + number(options.maxDeltaE)};
    for (std::size_t i = 0; i < labels.size(); ++i) {
      int w = textWidth(labels[i], 1);
      int x = i == 0 ? 0 : i == 1 ? tickX[1] - w / 2 : width - w;
      out.drawText(x, tickBottom + 2, labels[i], kInk, 1);
    }
  }
  return out;
}

PngImage deltaEHistogram(const FloatImage& deltaE, const HistogramOptions& options) {
  PRISM_CHECK(deltaE.channels == 1 && options.bins > 0 && options.maxDeltaE > 0.0);
  PRISM_CHECK(options.width >= 64 && options.height >= 48);
  // Bin i counts [i, i+1) × max/bins; the last bar counts ≥ max and non-finite values.
  std::vector<std::size_t> counts(static_cast<std::size_t>(options.bins) + 1, 0);
  for (float v : deltaE.pixels) {
    double t = std::isfinite(v) ? std::max(0.0, static_cast<double>(v)) / options.maxDeltaE * options.bins
                                : static_cast<double>(options.bins);
    counts[static_cast<std::size_t>(std::min(t, static_cast<double>(options.bins)))]++;
  }
  const std::size_t most = *std::max_element(counts.begin(), counts.end());

  constexpr int kLeft = 44, kRight = 8, kTop = 10, kBottom = 26;
  PngImage out(options.width, options.height, kBackground);
  const int plotW = options.width - kLeft - kRight, plotH = options.height - kTop - kBottom;
  const int axisY = kTop + plotH;
  // The overflow bar is drawn one bin-width to the right of the axis' end, after a gap.
  const double binW = static_cast<double>(plotW) / (options.bins + 1.5);
  auto xOf = [&](double deltaEValue) {
    return kLeft + static_cast<int>(std::lround(deltaEValue / options.maxDeltaE * options.bins * binW));
  };
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] == 0) continue;
    int h = std::max(
        1, static_cast<int>(std::lround(static_cast<double>(counts[i]) / static_cast<double>(most) * plotH)));
    bool overflow = i == counts.size() - 1;
    double start = overflow ? (options.bins + 0.5) * binW : static_cast<double>(i) * binW;
    int x0 = kLeft + static_cast<int>(std::lround(start));
    int x1 = kLeft + static_cast<int>(std::lround(start + binW));
    double centre =
        overflow ? options.maxDeltaE : (static_cast<double>(i) + 0.5) * options.maxDeltaE / options.bins;
    out.fillRect(x0, axisY - h, std::max(1, x1 - x0 - 1), h, heatColour(centre, options.maxDeltaE));
  }

  // Axes, ticks at whole ΔE values (thinned past 20 and 50), labels at 0, max/2 and max.
  out.fillRect(kLeft - 1, kTop, 1, plotH + 1, kInk);
  out.fillRect(kLeft - 1, axisY, xOf(options.maxDeltaE) - kLeft + 2, 1, kInk);
  const int step = options.maxDeltaE > 50 ? 10 : options.maxDeltaE > 20 ? 5 : 1;
  for (int v = 0; v <= static_cast<int>(options.maxDeltaE); v += step)
    out.fillRect(xOf(v), axisY + 1, 1, 3, kInk);
  for (double v : {0.0, options.maxDeltaE / 2, options.maxDeltaE}) {
    std::string label = number(v);
    out.fillRect(xOf(v), axisY + 1, 1, 5, kInk);
    out.drawText(xOf(v) - textWidth(label, 1) / 2, axisY + 8, label, kInk, 1);
  }
  std::string overflowLabel = ">=" + number(options.maxDeltaE);
  int overflowX = kLeft + static_cast<int>(std::lround((options.bins + 1.0) * binW));
  out.drawText(overflowX - textWidth(overflowLabel, 1) / 2, axisY + 16, overflowLabel, kInk, 1);
  out.fillRect(kLeft - 4, kTop, 3, 1, kInk);
  std::string top = std::to_string(most);
  out.drawText(std::max(0, kLeft - 6 - textWidth(top, 1)), kTop - 2, top, kInk, 1);
  out.drawText(2, axisY + 8, "dE00", kInk, 1);
  return out;
}

}  // namespace prism::imaging

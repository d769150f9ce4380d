#include "harness/prt_plot.h"

#include <fmt/format.h>

#include "harness/log_plot.h"

namespace prism::harness {

std::string basisSweepPlotSvg(const std::vector<BasisSweepPoint>& spectral, const BasisSweepPoint& rgb, double bound,
                              const std::string& title) {
  LogPlot plot;
  plot.title = title;
  plot.xLabel = "basis size m";
  plot.yLabel = "ΔE";
  plot.lowestDecade = -4;  // m = 16 is ~1e-4
  for (const BasisSweepPoint& p : spectral) plot.xTicks.push_back(p.m);
  struct Series {
    const char* label;
    double BasisSweepPoint::*field;
    const char* colour;
  };
  const Series series[] = {{"mean ΔE94", &BasisSweepPoint::mean94, "#1f77b4"},
                           {"max ΔE94", &BasisSweepPoint::max94, "#d62728"},
                           {"mean ΔE00", &BasisSweepPoint::mean2000, "#2ca02c"},
                           {"max ΔE00", &BasisSweepPoint::max2000, "#ff7f0e"}};
  for (const Series& k : series) {
    LogPlotLine line{k.label, k.colour, {}};
    for (const BasisSweepPoint& p : spectral) line.points.emplace_back(p.m, p.*k.field);
    plot.lines.push_back(std::move(line));
    plot.levels.push_back({"", k.colour, rgb.*k.field, /*dashed=*/true, /*thick=*/false});
  }
  plot.levels.push_back({"", "#888", bound, /*dashed=*/false, /*thick=*/true});
  plot.notes = {"dashed: RGB-PRT", fmt::format("grey: bound {}", bound)};
  return logPlotSvg(plot);
}

}  // namespace prism::harness

#include "harness/prt_plot.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace prism::harness {

std::string basisSweepPlotSvg(const std::vector<BasisSweepPoint>& spectral, const BasisSweepPoint& rgb, double bound,
                              const std::string& title) {
  const double width = 720, height = 440, left = 70, right = 190, top = 40, bottom = 50;
  const double plotW = width - left - right, plotH = height - top - bottom;
  // log10 ΔE from 1e-4 to 1e2: the sweep spans six decades (m = 16 is ~1e-4, m = 2 ~40).
  const double lo = -4.0, hi = 2.0;
  int mMax = 1;
  for (const BasisSweepPoint& p : spectral) mMax = std::max(mMax, p.m);
  auto x = [&](double m) { return left + plotW * (m - 1.0) / std::max(1.0, mMax - 1.0); };
  auto y = [&](double value) {
    double l = std::clamp(std::log10(std::max(value, 1e-12)), lo, hi);
    return top + plotH * (hi - l) / (hi - lo);
  };
  std::ostringstream s;
  s << fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
                   "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
                   width, height);
  s << fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, title);
  for (int d = static_cast<int>(lo); d <= static_cast<int>(hi); ++d) {
    s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", left, left + plotW,
                     y(std::pow(10.0, d)), y(std::pow(10.0, d)));
    s << fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">1e{}</text>\n", left - 6, y(std::pow(10.0, d)) + 4, d);
  }
  for (const BasisSweepPoint& p : spectral)
    s << fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", x(p.m), top + plotH + 18, p.m);
  s << fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">basis size m</text>\n", left + plotW / 2,
                   height - 10);
  s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#888\" stroke-width=\"2\"/>\n", left,
                   left + plotW, y(bound), y(bound));
  struct Series {
    const char* label;
    double BasisSweepPoint::*field;
    const char* colour;
  };
  const Series series[] = {{"mean ΔE94", &BasisSweepPoint::mean94, "#1f77b4"},
                           {"max ΔE94", &BasisSweepPoint::max94, "#d62728"},
                           {"mean ΔE00", &BasisSweepPoint::mean2000, "#2ca02c"},
                           {"max ΔE00", &BasisSweepPoint::max2000, "#ff7f0e"}};
  int row = 0;
  for (const Series& k : series) {
    std::string points;
    for (const BasisSweepPoint& p : spectral) points += fmt::format("{:.1f},{:.1f} ", x(p.m), y(p.*k.field));
    s << fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" points=\"{}\"/>\n", k.colour, points);
    s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-dasharray=\"6 4\"/>\n",
                     left, left + plotW, y(rgb.*k.field), y(rgb.*k.field), k.colour);
    double ly = top + 20.0 * row++;
    s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2\"/>", width - right + 15,
                     width - right + 40, ly, ly, k.colour);
    s << fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", width - right + 46, ly + 4, k.label);
  }
  double ly = top + 20.0 * row;
  s << fmt::format("<text x=\"{}\" y=\"{}\">dashed: RGB-PRT</text>\n", width - right + 15, ly + 4);
  s << fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#888\">grey: bound {}</text>\n", width - right + 15, ly + 24, bound);
  s << "</svg>\n";
  return s.str();
}

}  // namespace prism::harness

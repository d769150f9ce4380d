#include "harness/log_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "harness/html_report.h"

namespace prism::harness {

std::string logPlotSvg(const LogPlot& plot) {
  const double width = 720, height = 440, left = 70, right = 190, top = 40, bottom = 50;
  const double plotW = width - left - right, plotH = height - top - bottom;
  double xMin = std::numeric_limits<double>::max(), xMax = -xMin, yMin = xMin, yMax = 0.0;
  auto seeY = [&](double v) {
    if (v > 0.0 && std::isfinite(v)) {
      yMin = std::min(yMin, v);
      yMax = std::max(yMax, v);
    }
  };
  for (double t : plot.xTicks) xMin = std::min(xMin, t), xMax = std::max(xMax, t);
  for (const LogPlotLine& line : plot.lines)
    for (const auto& [x, y] : line.points) xMin = std::min(xMin, x), xMax = std::max(xMax, x), seeY(y);
  for (const LogPlotLevel& level : plot.levels) seeY(level.value);
  if (xMax < xMin) xMin = 0.0, xMax = 1.0;
  if (yMax <= 0.0) yMin = yMax = 1.0;
  const double lo = std::max<double>(plot.lowestDecade, std::floor(std::log10(yMin)));
  const double hi = std::max(lo + 1.0, std::ceil(std::log10(yMax)));
  auto x = [&](double v) { return left + plotW * (v - xMin) / std::max(xMax - xMin, 1e-12); };
  auto y = [&](double v) {
    const double l = std::clamp(std::log10(std::max(v, 1e-300)), lo, hi);
    return top + plotH * (hi - l) / (hi - lo);
  };
  std::ostringstream s;
  s << fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
                   "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
                   width, height);
  s << fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, htmlEscape(plot.title));
  for (int d = static_cast<int>(lo); d <= static_cast<int>(hi); ++d) {
    const double at = y(std::pow(10.0, d));
    s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", left, left + plotW, at, at);
    s << fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">1e{}</text>\n", left - 6, at + 4, d);
  }
  for (double t : plot.xTicks)
    s << fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", x(t), top + plotH + 18, t);
  s << fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", left + plotW / 2, height - 10,
                   htmlEscape(plot.xLabel));
  s << fmt::format("<text x=\"14\" y=\"{:.1f}\" text-anchor=\"middle\" transform=\"rotate(-90 14 {:.1f})\">{}</text>\n",
                   top + plotH / 2, top + plotH / 2, htmlEscape(plot.yLabel));
  int row = 0;
  auto legend = [&](const std::string& label, const std::string& colour, const std::string& style) {
    if (label.empty()) return;
    const double ly = top + 20.0 * row++;
    s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{}\" y2=\"{}\" stroke=\"{}\" {}/>", width - right + 15,
                     width - right + 40, ly, ly, colour, style);
    s << fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", width - right + 46, ly + 4, htmlEscape(label));
  };
  for (const LogPlotLevel& level : plot.levels) {
    const std::string style = fmt::format("stroke-width=\"{}\"{}", level.thick ? 2 : 1,
                                          level.dashed ? " stroke-dasharray=\"6 4\"" : "");
    s << fmt::format("<line x1=\"{}\" x2=\"{}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" {}/>\n", left, left + plotW,
                     y(level.value), y(level.value), level.colour, style);
    legend(level.label, level.colour, style);
  }
  for (const LogPlotLine& line : plot.lines) {
    std::string points;
    for (const auto& [px, py] : line.points) points += fmt::format("{:.1f},{:.1f} ", x(px), y(py));
    s << fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" points=\"{}\"/>\n", line.colour, points);
    for (const auto& [px, py] : line.points)
      s << fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n", x(px), y(py), line.colour);
    legend(line.label, line.colour, "stroke-width=\"2\"");
  }
  for (const std::string& note : plot.notes)
    s << fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", width - right + 15, top + 20.0 * row++ + 4, htmlEscape(note));
  s << "</svg>\n";
  return s.str();
}

}  // namespace prism::harness

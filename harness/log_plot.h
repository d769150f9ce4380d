// Error against a size, on a log scale, as an SVG: the plots of `prism prt report --plot` (colour
// error against the PRT basis size), `prism nebula basis --plot` (projection error after each
// greedy element) and `prism nebula sweep --plot` (a render's error against the basis size).
// Lines through points, horizontal levels (a baseline, a bound) and a legend; the y axis spans
// whole decades around every value shown.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace prism::harness {

struct LogPlotLine {
  std::string label;                              // in the legend; empty: none
  std::string colour;                             // SVG colour
  std::vector<std::pair<double, double>> points;  // (x, y > 0), in x order
};

struct LogPlotLevel {
  std::string label;   // in the legend; empty: none
  std::string colour;
  double value = 1.0;  // > 0
  bool dashed = false;
  bool thick = false;
};

struct LogPlot {
  std::string title, xLabel, yLabel;
  std::vector<double> xTicks;           // labelled on the x axis; its range is theirs and the points'
  std::vector<LogPlotLine> lines;
  std::vector<LogPlotLevel> levels;
  std::vector<std::string> notes;       // more legend lines, below the entries
  int lowestDecade = -12;               // the y axis never reaches below 10^lowestDecade
};

std::string logPlotSvg(const LogPlot& plot);

}  // namespace prism::harness

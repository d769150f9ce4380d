// The log plot's axis spans whole decades around what it shows, and it draws every point and level.
#include "harness/log_plot.h"

#include <string>

#include <gtest/gtest.h>

namespace prism::harness {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(LogPlot, SpansTheDecadesOfItsValuesAndDrawsEachPoint) {
  LogPlot plot;
  plot.title = "error < bound & more";
  plot.xTicks = {1, 2, 3};
  plot.lines.push_back({"error", "#d62728", {{1, 0.3}, {2, 4e-3}, {3, 2e-5}}});
  plot.levels.push_back({"bound", "#888", 0.02, false, true});
  const std::string svg = logPlotSvg(plot);
  EXPECT_NE(svg.find("error &lt; bound &amp; more"), std::string::npos);
  for (const char* decade : {">1e-5<", ">1e-4<", ">1e-3<", ">1e-2<", ">1e-1<", ">1e0<"})
    EXPECT_NE(svg.find(decade), std::string::npos) << decade;
  EXPECT_EQ(svg.find(">1e-6<"), std::string::npos);
  EXPECT_EQ(svg.find(">1e1<"), std::string::npos);
  EXPECT_EQ(count(svg, "<circle"), 3u);
  EXPECT_EQ(count(svg, "<polyline"), 1u);
  EXPECT_NE(svg.find(">bound<"), std::string::npos);

  plot.lowestDecade = -3;  // values below it sit on the axis's floor
  const std::string floored = logPlotSvg(plot);
  EXPECT_NE(floored.find(">1e-3<"), std::string::npos);
  EXPECT_EQ(floored.find(">1e-4<"), std::string::npos);
}

}  // namespace
}  // namespace prism::harness

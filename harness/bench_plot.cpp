#include "harness/bench_plot.h"

#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "harness/html_report.h"

namespace prism::harness {

std::string benchPlotSvg(const std::vector<BenchPoint>& spectral, double rgbMs, const LinearFit& fit,
                         const std::string& title) {
  const double w = 640, h = 400, left = 70, right = 20, top = 40, bottom = 50;
  const double a = fit.slope, b = fit.intercept;
  double maxN = 0, maxT = rgbMs;
  for (const BenchPoint& p : spectral) {
    maxN = std::max(maxN, static_cast<double>(p.wavelengths));
    maxT = std::max({maxT, p.frameMs, p.maxFrameMs});
  }
  maxT *= 1.1;
  auto x = [&](double n) { return left + n / maxN * (w - left - right); };
  auto y = [&](double t) { return h - bottom - t / maxT * (h - top - bottom); };
  std::ostringstream s;
  s << fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                   "font-family=\"sans-serif\" font-size=\"12\">\n", w, h);
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, htmlEscape(title));
  s << fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>\n", left,
                   h - bottom, w - right);
  s << fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"black\"/>\n", left,
                   h - bottom, top);
  for (int i = 0; i <= 4; ++i) {
    double t = maxT * i / 4, n = maxN * i / 4;
    s << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{:.3g}</text>\n", left - 6,
                     y(t) + 4, t);
    s << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{:.0f}</text>\n", x(n),
                     h - bottom + 18, n);
  }
  s << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">wavelengths n</text>\n",
                   (left + w - right) / 2, h - 8);
  s << fmt::format("<text x=\"16\" y=\"{}\" transform=\"rotate(-90 16 {})\" "
                   "text-anchor=\"middle\">frame time (ms)</text>\n", (top + h - bottom) / 2,
                   (top + h - bottom) / 2);
  s << fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#c33\" "
                   "stroke-dasharray=\"6 4\"/>\n", x(0), y(rgbMs), x(maxN), y(rgbMs));
  s << fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#c33\" text-anchor=\"end\">RGB {:.3g} ms</text>\n",
                   w - right, y(rgbMs) - 6, rgbMs);
  const bool fitted = spectral.size() > 1;  // a line through one point is no measurement
  if (fitted)
    s << fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#36c\"/>\n", x(0), y(b),
                     x(maxN), y(a * maxN + b));
  for (const BenchPoint& p : spectral) {
    s << fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#36c\"/>\n", x(p.wavelengths),
                     y(p.minFrameMs), y(p.maxFrameMs));
    s << fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"#36c\"/>\n", x(p.wavelengths), y(p.frameMs));
  }
  if (fitted)
    s << fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#36c\">t(n) = {:.4g} ms·n + {:.4g} ms</text>\n",
                     left + 10, top + 14, a, b);
  s << "</svg>\n";
  return s.str();
}

}  // namespace prism::harness

#include "core/gauss_legendre.h"

#include <cmath>
#include <cstddef>
#include <numbers>

#include "core/error.h"

namespace prism {

void gaussLegendre(int n, double a, double b, std::vector<double>& nodes, std::vector<double>& weights) {
  PRISM_CHECK(n >= 1);
  nodes.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {  // Newton on Pₙ from Chebyshev's guess (Numerical Recipes 3rd ed., §4.6.1)
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {
        double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p2) / k;
      }
      dp = n * (x * p0 - p1) / (x * x - 1.0);
      double dx = p0 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    nodes[static_cast<std::size_t>(i)] = 0.5 * (a + b) - 0.5 * (b - a) * x;
    weights[static_cast<std::size_t>(i)] = (b - a) / ((1.0 - x * x) * dp * dp);
  }
}

}  // namespace prism

#include "core/gauss_legendre.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace prism {
namespace {

TEST(GaussLegendre, IntegratesPolynomialsUpToDegreeTwoNMinusOneExactly) {
  std::vector<double> nodes, weights;
  for (int n : {1, 2, 5, 16, 64}) {
    gaussLegendre(n, 0.38, 0.78, nodes, weights);
    for (int degree = 0; degree <= 2 * n - 1 && degree <= 40; ++degree) {
      double sum = 0.0;
      for (std::size_t i = 0; i < nodes.size(); ++i) sum += weights[i] * std::pow(nodes[i], degree);
      double exact = (std::pow(0.78, degree + 1) - std::pow(0.38, degree + 1)) / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-13 * std::max(1.0, std::abs(exact))) << n << " nodes, degree " << degree;
    }
  }
}

TEST(GaussLegendre, NodesAscendInsideTheIntervalAndWeightsArePositive) {
  std::vector<double> nodes, weights;
  gaussLegendre(9, -1.0, 1.0, nodes, weights);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_GT(nodes[i], -1.0);
    EXPECT_LT(nodes[i], 1.0);
    EXPECT_GT(weights[i], 0.0);
    if (i > 0) {
      EXPECT_GT(nodes[i], nodes[i - 1]);
    }
    EXPECT_NEAR(nodes[i], -nodes[nodes.size() - 1 - i], 1e-15);  // symmetric about the middle
  }
  EXPECT_NEAR(nodes[4], 0.0, 1e-15);
}

}  // namespace
}  // namespace prism

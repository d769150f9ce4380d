// Gauss–Legendre quadrature: the n nodes (ascending) and weights on [a, b] that integrate every
// polynomial of degree ≤ 2n − 1 exactly. The nebula's spectral projections and the PRT's SH
// projections both integrate smooth functions with it.
#pragma once

#include <vector>

namespace prism {

void gaussLegendre(int n, double a, double b, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace prism

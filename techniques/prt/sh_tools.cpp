#include "techniques/prt/sh_tools.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/QR>

#include "core/error.h"

namespace prism::prt {
namespace {

// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n; Press et al., Numerical Recipes
// 3rd ed., §4.6.1).
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double pp = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p1 = 1.0, p2 = 0.0;
      for (int j = 1; j <= n; ++j) {
        double p3 = p2;
        p2 = p1;
        p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j;
      }
      pp = n * (z * p1 - p2) / (z * z - 1.0);
      double z1 = z;
      z = z1 - p1 / pp;
      if (std::abs(z - z1) < 1e-15) break;
    }
    nodes[static_cast<std::size_t>(i)] = -z;
    nodes[static_cast<std::size_t>(n - 1 - i)] = z;
    weights[static_cast<std::size_t>(i)] = weights[static_cast<std::size_t>(n - 1 - i)] = 2.0 / ((1.0 - z * z) * pp * pp);
  }
}

// Spherical Fibonacci points (González 2010): well spread, deterministic.
glm::dvec3 fibonacciDirection(int i, int count) {
  double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  double z = 1.0 - (2.0 * i + 1.0) / count;
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  double phi = 2.0 * std::numbers::pi * std::fmod(i / golden, 1.0);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

ShVector toShVector(const shared::Sh25& s) {
  ShVector v;
  for (int k = 0; k < 25; ++k) v[k] = s.c[k];
  return v;
}

shared::Sh25 toSh25(const ShVector& v) {
  shared::Sh25 s;
  for (int k = 0; k < 25; ++k) s.c[k] = static_cast<float>(v[k]);
  return s;
}

ShVector evaluateSh(const glm::dvec3& d) {
  // The shared (float) basis, so that no polynomial is typed twice: ~1e-7 relative, far below
  // every tolerance that projections and rotations are held to.
  return toShVector(shared::shEvaluate(glm::vec3(d)));
}

ShVector projectOnSh(const std::function<double(const glm::dvec3&)>& f, int zNodes, int phiSteps) {
  PRISM_CHECK(zNodes > 0 && phiSteps > 0);
  std::vector<double> nodes, weights;
  gaussLegendre(zNodes, nodes, weights);
  ShVector sum = ShVector::Zero();
  double dPhi = 2.0 * std::numbers::pi / phiSteps;
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    for (int i = 0; i < zNodes; ++i) {
      // [−1, 1] → [0, 1] or [−1, 0]: half the weight.
      double z = 0.5 * (nodes[static_cast<std::size_t>(i)] + 1.0) * (hemisphere == 0 ? 1.0 : -1.0);
      double w = 0.5 * weights[static_cast<std::size_t>(i)] * dPhi;
      double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      for (int j = 0; j < phiSteps; ++j) {
        double phi = (j + 0.5) * dPhi;
        glm::dvec3 dir(r * std::cos(phi), r * std::sin(phi), z);
        sum += (w * f(dir)) * evaluateSh(dir);
      }
    }
  }
  return sum;
}

ShRotation shRotation(const glm::dmat3& rotation) {
  ShRotation d = ShRotation::Zero();
  glm::dmat3 inverse = glm::transpose(rotation);
  for (int l = 0; l < 5; ++l) {
    int size = 2 * l + 1, first = l * l, count = 2 * size;
    Eigen::MatrixXd a(count, size), b(count, size);
    for (int i = 0; i < count; ++i) {
      glm::dvec3 dir = fibonacciDirection(i, count);
      a.row(i) = evaluateSh(dir).segment(first, size).transpose();
      b.row(i) = evaluateSh(inverse * dir).segment(first, size).transpose();
    }
    // f'(ω_i) = Σ_m c'_m Y_m(ω_i) = Σ_n c_n Y_n(Rᵀω_i): A c' = B c.
    d.block(first, first, size, size) = a.colPivHouseholderQr().solve(b);
  }
  return d;
}

}  // namespace prism::prt

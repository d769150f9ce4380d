#include "techniques/prt/sh_tools.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/QR>

#include "core/error.h"
#include "core/gauss_legendre.h"

namespace prism::prt {
namespace {

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
  gaussLegendre(zNodes, -1.0, 1.0, nodes, weights);
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

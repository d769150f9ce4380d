#include "techniques/nebula/nebula_basis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "core/error.h"
#include "core/gauss_legendre.h"
#include "techniques/nebula/nebula_integrals.h"
#include "techniques/nebula/nebula_spectra.h"

namespace prism::nebula {

GreedyResult greedyBasis(const Eigen::MatrixXd& family, const Eigen::MatrixXd& candidates,
                         const Eigen::VectorXd& weights, int count, const std::vector<int>& initial,
                         const std::vector<double>& keys, double minKeySeparation, double minNewDirection) {
  Eigen::VectorXd sw = weights.cwiseSqrt();
  Eigen::MatrixXd F = sw.asDiagonal() * family, C = sw.asDiagonal() * candidates;
  Eigen::VectorXd norms = F.colwise().norm().transpose();
  Eigen::MatrixXd residual = F;  // of the family, against the basis so far
  Eigen::MatrixXd basis(F.rows(), 0);
  GreedyResult result;
  auto add = [&](int c) {
    Eigen::VectorXd u = C.col(c) - basis * (basis.transpose() * C.col(c));
    u -= basis * (basis.transpose() * u);  // twice: Gram–Schmidt loses orthogonality on near-collinear exponentials
    u.normalize();
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = u;
    residual -= u * (u.transpose() * residual);
    result.chosen.push_back(c);
    double worst = 0.0;
    for (Eigen::Index j = 0; j < residual.cols(); ++j) worst = std::max(worst, residual.col(j).norm() / norms(j));
    result.maxError.push_back(worst);
  };
  // A candidate that vanishes over the domain (e^(−a/λ) past double's range: a = 288 µm under
  // 1 µm) has no direction of its own, and its part "orthogonal" to the basis is rounding noise
  // however large relative to it: the same one was chosen again and again.
  const double largest = C.colwise().norm().maxCoeff();
  for (int c : initial) add(c);
  while (static_cast<int>(result.chosen.size()) < count) {
    int best = -1;
    double bestError = std::numeric_limits<double>::infinity();
    for (int c = 0; c < C.cols(); ++c) {
      bool near = false;
      if (!keys.empty())
        for (int k : result.chosen)
          near = near || std::abs(keys[static_cast<std::size_t>(c)] - keys[static_cast<std::size_t>(k)]) <
                             minKeySeparation - 1e-12;
      if (near || std::find(result.chosen.begin(), result.chosen.end(), c) != result.chosen.end()) continue;
      if (!(C.col(c).norm() >= minNewDirection * largest)) continue;
      Eigen::VectorXd u = C.col(c) - basis * (basis.transpose() * C.col(c));
      double n = u.norm();
      if (n < minNewDirection * C.col(c).norm()) continue;
      u /= n;
      // Element by element: the row-minus-column array expression this was read past its end
      // under ASan.
      Eigen::RowVectorXd proj = u.transpose() * residual;
      double worst = 0.0;
      for (Eigen::Index j = 0; j < residual.cols(); ++j) {
        double err2 = residual.col(j).squaredNorm() - proj(j) * proj(j);
        worst = std::max(worst, std::sqrt(std::max(err2, 0.0)) / norms(j));
      }
      if (worst < bestError) bestError = worst, best = c;
    }
    if (best < 0) break;
    add(best);
  }
  return result;
}

double ExpBasis::at(int k, double lambdaUm) const {
  double v = 0.0;
  for (int j = 0; j <= k; ++j) v += m(k, j) * std::exp(-a[static_cast<std::size_t>(j)] / lambdaUm);
  return v;
}

Eigen::MatrixXd orthonormaliser(const std::vector<double>& a, double l0, double l1) {
  auto n = static_cast<Eigen::Index>(a.size());
  // By 256-node Gauss–Legendre rather than nebulaExpIntegral: the Gram matrix of near-collinear
  // exponentials needs more digits than E₁'s 4e-8 (its condition number passes 1e8 at 5 elements).
  std::vector<double> nodes, weights;
  gaussLegendre(256, l0, l1, nodes, weights);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t q = 0; q < nodes.size(); ++q)
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        g(i, j) += weights[q] * std::exp(-(a[static_cast<std::size_t>(i)] + a[static_cast<std::size_t>(j)]) / nodes[q]);
  Eigen::LLT<Eigen::MatrixXd> llt(g);
  if (llt.info() != Eigen::Success)
    throw Error(fmt::format("nebula basis: {} exponentials cannot be orthonormalised in double (their Gram matrix is "
                            "singular to its rounding); use fewer elements", n));
  Eigen::MatrixXd l = llt.matrixL();
  return l.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(n, n));
}

ExpBasis findExpBasis(double lambda0Um, double lambda1Um, double gMaxUm, double aMaxUm, int count,
                      double minSpacingUm, bool orthonormalise) {
  std::vector<double> nodes, weights;
  // 256 Gauss–Legendre nodes: e^(−a/λ) is smooth on the interval, to λ → 0 where it vanishes
  // with all its derivatives.
  gaussLegendre(256, lambda0Um, lambda1Um, nodes, weights);
  auto q = static_cast<Eigen::Index>(nodes.size());
  const int familySize = 64, candidateCount = 401;
  Eigen::MatrixXd family(q, familySize), candidates(q, candidateCount);
  std::vector<double> keys;
  for (int c = 0; c < candidateCount; ++c) keys.push_back(aMaxUm * c / (candidateCount - 1));
  for (Eigen::Index i = 0; i < q; ++i) {
    double l = nodes[static_cast<std::size_t>(i)];
    for (int f = 0; f < familySize; ++f) family(i, f) = std::exp(-gMaxUm * f / (familySize - 1) / l);
    for (int c = 0; c < candidateCount; ++c) candidates(i, c) = std::exp(-aMaxUm * c / (candidateCount - 1) / l);
  }
  GreedyResult g = greedyBasis(family, candidates, Eigen::Map<Eigen::VectorXd>(weights.data(), q), count, {0}, keys,
                                minSpacingUm);
  ExpBasis basis;
  basis.lambda0Um = lambda0Um;
  basis.lambda1Um = lambda1Um;
  for (int c : g.chosen) basis.a.push_back(aMaxUm * c / (candidateCount - 1));
  basis.maxError = g.maxError;
  if (orthonormalise) basis.m = orthonormaliser(basis.a, lambda0Um, lambda1Um);
  return basis;
}

ExpBasis restrictExpBasis(const ExpBasis& basis, int count) {
  ExpBasis r = basis;
  r.a.resize(static_cast<std::size_t>(count));
  r.maxError.resize(static_cast<std::size_t>(count));
  r.m = orthonormaliser(r.a, r.lambda0Um, r.lambda1Um);
  return r;
}

}  // namespace prism::nebula

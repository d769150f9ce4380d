// The greedy bases of Barrès 2023 (§5): a small set of functions on which the attenuations
// e^(−g/λ) (1D basis) or the lit spectra S_T(λ)·e^(−g/λ) (2D light–density basis) project with a
// small worst-case L2 error. Each step adds the candidate that most reduces the worst relative
// projection error ‖f − Πf‖/‖f‖ over the family, then orthonormalises (Gram–Schmidt).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace prism::nebula {

// Functions sampled at quadrature nodes: column j of `family` / `candidates` is a function's
// values; `weights` the nodes' quadrature weights (the L2 inner product is Σ wᵢ f(λᵢ) g(λᵢ)).
struct GreedyResult {
  std::vector<int> chosen;         // candidate indices, in the order added
  std::vector<double> maxError;    // the worst relative projection error after each addition
};
// A candidate whose key (its exponent a) is within minKeySeparation of a chosen one's is skipped,
// and so is one chosen already, one whose norm is below minNewDirection of the largest candidate's
// (it vanishes over the domain), or one whose part orthogonal to the basis is below minNewDirection
// of its norm (which bounds the Gram matrix's conditioning); the result may then hold fewer than
// `count` elements.
GreedyResult greedyBasis(const Eigen::MatrixXd& family, const Eigen::MatrixXd& candidates,
                         const Eigen::VectorXd& weights, int count, const std::vector<int>& initial,
                         const std::vector<double>& keys = {}, double minKeySeparation = 0.0,
                         double minNewDirection = 1e-10);

// The 1D basis {e^(−aⱼ/λ)} on [λ₀, λ₁] (µm): its exponents and the matrix M whose row k gives the
// k-th orthonormal function as Σⱼ M(k,j)·e^(−aⱼ/λ) (the inverse Cholesky factor of the exact Gram
// matrix, ∫ e^(−(aᵢ+aⱼ)/λ) dλ by quadrature in double; Error when it is singular in double).
struct ExpBasis {
  double lambda0Um = 0.0, lambda1Um = 1.0;
  std::vector<double> a;      // µm
  Eigen::MatrixXd m;          // card × card, lower triangular
  std::vector<double> maxError;
  double at(int k, double lambdaUm) const;  // the k-th orthonormal function
};
// Greedy over candidates a ∈ [0, aMaxUm] (step aMaxUm/400) for the family g ∈ [0, gMaxUm]
// (64 values), starting from {1} (a = 0). Left free (minSpacingUm = 0) the greedy takes each new
// exponent next to one it has (a → aⱼ adds the derivative direction −e^(−aⱼ/λ)/λ, which is what
// reduces the error most): the elements approach 1, 1/λ, 1/λ², … and the matrix M grows beyond
// float's reach. A minimum spacing between exponents keeps M usable on the GPU at the price of a
// larger error per element (README, "Spectral nebulae", gives both tables).
// With orthonormalise = false, M is left empty (the table alone: the free greedy's M is singular
// in double beyond about 4 elements).
ExpBasis findExpBasis(double lambda0Um, double lambda1Um, double gMaxUm, double aMaxUm, int count,
                      double minSpacingUm = 0.0, bool orthonormalise = true);
// M for exponents a on [l0, l1] (Error when their Gram matrix is singular in double).
Eigen::MatrixXd orthonormaliser(const std::vector<double>& a, double l0, double l1);
// The same elements, re-orthonormalised on another interval (the first `count` of them).
ExpBasis restrictExpBasis(const ExpBasis& basis, int count);

}  // namespace prism::nebula

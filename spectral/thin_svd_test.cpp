#include "spectral/thin_svd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include <Eigen/QR>

namespace prism {
namespace {

// A = Q₁·diag(σ)·Q₂ᵀ with known σ, wide (81 × 200, as a scene's spectra) and tall.
TEST(ThinSvd, FindsTheSingularValuesAndAnOrthonormalBasisOfTheColumns) {
  for (auto [rows, cols] : {std::pair{81, 200}, std::pair{81, 12}}) {
    const int k = std::min(rows, cols);
    std::srand(5);
    Eigen::MatrixXd q1 = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(rows, k)).householderQ() *
                         Eigen::MatrixXd::Identity(rows, k);
    Eigen::MatrixXd q2 = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(cols, k)).householderQ() *
                         Eigen::MatrixXd::Identity(cols, k);
    Eigen::VectorXd sigma(k);
    for (int i = 0; i < k; ++i) sigma[i] = std::pow(0.7, i);  // down to 3e-13 at 81
    const Eigen::MatrixXd a = q1 * sigma.asDiagonal() * q2.transpose();

    const LeftSingularVectors s = leftSingularVectors(a);
    ASSERT_EQ(s.vectors.rows(), rows);
    ASSERT_EQ(s.vectors.cols(), k);
    ASSERT_EQ(s.values.size(), k);
    for (int i = 0; i < k; ++i) EXPECT_NEAR(s.values[i], sigma[i], 1e-13) << i;
    EXPECT_LT((s.vectors.transpose() * s.vectors - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff(), 1e-13);
    // The leading vectors span the leading directions: |uᵢ·q1ᵢ| = 1 for well separated σ.
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(std::abs(s.vectors.col(i).dot(q1.col(i))), 1.0, 1e-12) << i;
    EXPECT_LT((s.vectors * s.vectors.transpose() * a - a).cwiseAbs().maxCoeff(), 1e-13);
  }
}

// A column's sign is the SVD's own choice; fixed here, the same matrix and its columns' negations
// give one basis (a spectral texture's file the same bytes whichever SVD wrote it).
TEST(ThinSvd, SignsEachVectorByItsLargestEntry) {
  std::srand(11);
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(81, 12);
  const LeftSingularVectors s = leftSingularVectors(a);
  const LeftSingularVectors negated = leftSingularVectors(-a);
  for (Eigen::Index c = 0; c < s.vectors.cols(); ++c) {
    Eigen::Index largest = 0;
    s.vectors.col(c).cwiseAbs().maxCoeff(&largest);
    EXPECT_GT(s.vectors(largest, c), 0.0) << c;
  }
  EXPECT_LT((s.vectors - negated.vectors).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace prism

#include "spectral/thin_svd.h"

#include <Eigen/SVD>

namespace prism {

LeftSingularVectors leftSingularVectors(const Eigen::MatrixXd& m) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinU);
  LeftSingularVectors out{svd.matrixU(), svd.singularValues()};
  for (Eigen::Index c = 0; c < out.vectors.cols(); ++c) {
    Eigen::Index largest = 0;
    out.vectors.col(c).cwiseAbs().maxCoeff(&largest);
    if (out.vectors(largest, c) < 0.0) out.vectors.col(c) *= -1.0;
  }
  return out;
}

}  // namespace prism

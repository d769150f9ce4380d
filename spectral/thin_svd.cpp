#include "spectral/thin_svd.h"

#include <Eigen/SVD>

namespace prism {

LeftSingularVectors leftSingularVectors(const Eigen::MatrixXd& m) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinU);
  return {svd.matrixU(), svd.singularValues()};
}

}  // namespace prism

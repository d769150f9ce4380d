// The left singular vectors and singular values of a matrix: its thin singular value
// decomposition, for the spectral bases of PRT and of spectral textures (Peercy 1993). Eigen's
// Jacobi SVD (two-sided, after a QR), the more accurate of its two and, at Prism's sizes (81 wavelengths by
// tens to thousands of spectra), milliseconds. Kept in one translation unit: the decomposition's
// templates cost 8 s to compile (20 s under the sanitizers), the divide-and-conquer one's 33 s
// (65 s), and two files each compiled their own.
#pragma once

#include <Eigen/Core>

namespace prism {

struct LeftSingularVectors {
  // rows × min(rows, cols), orthonormal columns, each signed so that its entry of largest
  // magnitude is positive: a basis written to a file is the same whichever SVD made it.
  Eigen::MatrixXd vectors;
  Eigen::VectorXd values;   // min(rows, cols) singular values, largest first
};

LeftSingularVectors leftSingularVectors(const Eigen::MatrixXd& m);

}  // namespace prism

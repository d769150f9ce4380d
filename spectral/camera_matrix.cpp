#include "spectral/camera_matrix.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>

#include "spectral/colour_checker.h"
#include "spectral/colour_difference.h"
#include "spectral/illuminant.h"

namespace prism {

bool cameraSees(const Observer& camera, const Spectrum& light) {
  const Observer& cie = cie1931Observer();
  const Spectrum& d65 = illuminant("D65");
  const double y = cie.integrate(light).y();
  return y > 0.0 && camera.integrate(light).y() / y >= 1e-6 * camera.integrate(d65).y() / cie.integrate(d65).y();
}

CameraMatrixFit fitCameraToXyz(const Observer& camera, const Spectrum& illuminant,
                               const Observer& target) {
  const auto& patches = colourChecker();
  const auto n = static_cast<Eigen::Index>(patches.size());
  Eigen::MatrixX3d cameraRgb(n, 3), xyz(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Spectrum& r = patches[static_cast<std::size_t>(i)].reflectance;
    cameraRgb.row(i) = reflectanceTristimulus(camera, r, illuminant).transpose();
    xyz.row(i) = reflectanceTristimulus(target, r, illuminant).transpose();
  }
  // min ‖cameraRgb·Mᵀ − xyz‖²: one least-squares problem per XYZ channel.
  CameraMatrixFit fit;
  fit.cameraToXyz = cameraRgb.colPivHouseholderQr().solve(xyz).transpose();
  const Eigen::Vector3d singular = Eigen::JacobiSVD<Eigen::MatrixX3d>(cameraRgb).singularValues();
  fit.chartConditioning = singular[0] > 0.0 ? singular[2] / singular[0] : 0.0;
  Eigen::Vector3d white = whiteTristimulus(target, illuminant);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Vector3d fitted = fit.cameraToXyz * cameraRgb.row(i).transpose();
    double d = deltaE(xyzToLab(fitted, white), xyzToLab(xyz.row(i).transpose(), white));
    sum += d;
    fit.maxDeltaE2000 = std::max(fit.maxDeltaE2000, d);
  }
  fit.meanDeltaE2000 = sum / static_cast<double>(n);
  return fit;
}

}  // namespace prism

// Camera raw RGB → XYZ, the 3×3 matrix a raw photo pipeline applies: fitted by least squares
// over the 24 ColorChecker patches under a chosen illuminant, both sides normalised so that a
// perfect white has Y (camera G) = 1. Reports how well the fit reproduces the chart.
#pragma once

#include <Eigen/Core>

#include "spectral/observer.h"

namespace prism {

struct CameraMatrixFit {
  Eigen::Matrix3d cameraToXyz;
  double meanDeltaE2000 = 0.0;  // over the 24 patches, CIELAB relative to the illuminant's white
  double maxDeltaE2000 = 0.0;
};

CameraMatrixFit fitCameraToXyz(const Observer& camera, const Spectrum& illuminant,
                               const Observer& target);

}  // namespace prism

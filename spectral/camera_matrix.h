// Camera raw RGB → XYZ, the 3×3 matrix a raw photo pipeline applies: fitted by least squares
// over the 24 ColorChecker patches under a chosen illuminant, both sides normalised so that a
// perfect white has Y (camera G) = 1. Reports how well the fit reproduces the chart, and how well
// the chart pins the matrix down under that light.
#pragma once

#include <Eigen/Core>

#include "spectral/observer.h"

namespace prism {

struct CameraMatrixFit {
  Eigen::Matrix3d cameraToXyz;
  double meanDeltaE2000 = 0.0;  // over the 24 patches, CIELAB relative to the illuminant's white
  double maxDeltaE2000 = 0.0;
  // The chart's camera RGBs' smallest singular value over their largest. Under a narrow light
  // they nearly share one direction, and the matrix, one of many that fit them, maps light of
  // another spectrum arbitrarily (entries of ±57 000 under led:790:5).
  double chartConditioning = 0.0;
};
// Below it, a fit is said to be ill-posed (the D850 under D65, A and F11: 0.08–0.12; under a white
// LED lamp, led-globe-a19, 0.0026; a 20 nm LED, led:450:20, 5e-5).
inline constexpr double kIllPosedCameraFit = 1e-3;

// Whether the camera sees the light, so that its frames have a white to normalise to and a chart
// to fit: its G of the light over CIE 1931 Y of it at least 1e-6 of the same for D65. Under
// led:790:5, past the D850's curves (they end at 720 nm), G was 1e-89: taken as seen, the fit
// scaled by 1e84; led:790:2 underflowed to 0 and was refused.
bool cameraSees(const Observer& camera, const Spectrum& light);

CameraMatrixFit fitCameraToXyz(const Observer& camera, const Spectrum& illuminant,
                               const Observer& target);

}  // namespace prism

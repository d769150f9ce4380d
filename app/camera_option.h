// The --camera option of render, view, bench, reference, wavelengths and colour camera-matrix: a
// camera of the observer table (raw camera RGB), named the same way everywhere.
#pragma once

#include <string>
#include <string_view>

#include "spectral/camera_matrix.h"
#include "spectral/observer.h"

namespace prism::app {

// The camera of that name; Error "--camera: "NAME" is not a camera (see `prism colour list
// cameras`)" for a CIE observer and for an unknown name alike (an unknown one was "unknown
// observer", pointing at the observers' list).
const Observer& cameraOption(const std::string& name);

// The warning, on stderr, that a camera matrix fitted under `light` is one of many that fit the
// chart (chartConditioning below kIllPosedCameraFit): what `colour camera-matrix` prints, and
// `render` for the matrix its images go through (a narrow LED's).
void warnIfIllPosed(double chartConditioning, std::string_view light, std::string_view camera);

}  // namespace prism::app

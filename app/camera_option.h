// The --camera option of render, view, bench, reference, wavelengths and colour camera-matrix: a
// camera of the observer table (raw camera RGB), named the same way everywhere.
#pragma once

#include <string>

#include "spectral/observer.h"

namespace prism::app {

// The camera of that name; Error "--camera: "NAME" is not a camera (see `prism colour list
// cameras`)" for a CIE observer and for an unknown name alike (an unknown one was "unknown
// observer", pointing at the observers' list).
const Observer& cameraOption(const std::string& name);

}  // namespace prism::app

// The --camera option of render, view, bench, reference, wavelengths and colour camera-matrix: a
// camera of the observer table (raw camera RGB), named the same way everywhere.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "spectral/observer.h"

namespace prism::app {

// The camera of that name; Error "--camera: "NAME" is not a camera (see `prism colour list
// cameras`)" for a CIE observer and for an unknown name alike (an unknown one was "unknown
// observer", pointing at the observers' list).
const Observer& cameraOption(const std::string& name);

// CLI11's check of a --camera value, as it is parsed: not empty (given empty, it was taken for no
// camera, and a script's unset variable rendered CIE 1931 XYZ without a word). A malformed command
// line, exit 2; a name that is no camera's is bad input, cameraOption's, exit 1.
CLI::Validator cameraName();

}  // namespace prism::app

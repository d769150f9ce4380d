// The dual-compiled PRT headers (shaders/shared/spherical_harmonics.glsl, prt.glsl) as C++,
// inside prism::shared, once for every file of prism::prt and its users.
#pragma once

#include "shared_cpp.h"

namespace prism::shared {
#include "spherical_harmonics.glsl"
#include "prt.glsl"
}  // namespace prism::shared

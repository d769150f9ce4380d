// The dual-compiled PRT headers (shaders/shared/spherical_harmonics.glsl, prt.glsl, prt_medium.glsl)
// as C++, inside prism::shared, once for every file of prism::prt and its users.
#pragma once

#include "shared_cpp.h"

namespace prism::shared {
#include "spherical_harmonics.glsl"
#include "prt.glsl"
#include "prt_medium.glsl"

// The forward pass's std430 buffers (prt.glsl): sizes as the GPU lays them out.
static_assert(sizeof(Sh25) == 100);
static_assert(sizeof(PrtEnvironment) == 16 * 100);
static_assert(sizeof(PrtGpuMaterial) == 16 * 16);
static_assert(sizeof(PrtMediumNode) == 5 * 16);
}  // namespace prism::shared

// shaders/shared/atmosphere_model.glsl compiled as C++ (inside prism::shared): the GPU layout of
// a batch's atmosphere and the model's geometry and quadrature, shared by the tables' CPU twin
// and the renderer.
#pragma once

#include <cstddef>

#include "shared_cpp.h"

namespace prism::shared {
#include "atmosphere_model.glsl"

static_assert(sizeof(GpuAtmosphere) == 8 * 16);  // std430: vec4 members only
static_assert(sizeof(SkyConstants) == 16 && offsetof(SkyConstants, sunLight) == 4);  // std140: one vec4
}  // namespace prism::shared

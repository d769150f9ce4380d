// shaders/shared/atmosphere_model.glsl compiled as C++ (inside prism::shared): the GPU layout of
// a batch's atmosphere and the model's geometry and quadrature, shared by the tables' CPU twin
// and the renderer.
#pragma once

#include "shared_cpp.h"

namespace prism::shared {
#include "atmosphere_model.glsl"

static_assert(sizeof(GpuAtmosphere) == 8 * 16);  // std430: vec4 members only
}  // namespace prism::shared

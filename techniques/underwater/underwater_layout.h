// shaders/shared/underwater.glsl compiled as C++ (inside prism::shared), once per translation
// unit: the analytic model and the layout of the water's block of the lighting pass, shared by
// the section's packing (water_section.h), the renderer's CPU twin and the tests.
#pragma once

#include "shared_cpp.h"

namespace prism::shared {
#include "underwater.glsl"

static_assert(sizeof(WaterConstants) == 16);  // std140: one vec4
}  // namespace prism::shared

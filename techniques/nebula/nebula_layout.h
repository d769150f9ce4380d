// shaders/shared/nebula_lighting.glsl compiled as C++ (inside prism::shared), once per translation
// unit: the layout of the nebula's block of the lighting pass and its per-pixel formulas, shared by
// the section's packing (nebula_section.h), the CPU twin (nebula_cpu_twin.h) and the tests.
#pragma once

#include "shared_cpp.h"
#include "techniques/nebula/nebula_integrals.h"  // nebula_march.glsl, which nebula_lighting.glsl requires

namespace prism::shared {
#include "nebula_lighting.glsl"

static_assert(sizeof(NebulaLightConstants) == 32);  // std140: two vec4s
}  // namespace prism::shared

// The nebula's shared integrals (shaders/shared/nebula_integrals.glsl) and the marcher's
// per-sample formulas (nebula_march.glsl) compiled as C++ twice: in float inside prism::shared
// (what the GPU runs; the CPU renderer's per-sample path) and in double inside
// prism::shared::f64 (the basis search, the per-frame tables and the march's geometry, which need
// the digits).
#pragma once

#include <cmath>

#include "shared_cpp.h"

namespace prism::shared {
using glm::log;
#include "nebula_integrals.glsl"
#include "nebula_march.glsl"
#undef NEBULA_REAL
#undef NEBULA_VEC4
#undef NEBULA_VEC3
#undef NEBULA_CF_DEPTH

namespace f64 {
using vec4 = glm::dvec4;
using std::exp;
using std::log;
#define NEBULA_REAL double
#define NEBULA_VEC4 vec4
#define NEBULA_VEC3 glm::dvec3
#define NEBULA_CF_DEPTH 96
#include "nebula_integrals.glsl"
#include "nebula_march.glsl"
#undef NEBULA_REAL
#undef NEBULA_VEC4
#undef NEBULA_VEC3
#undef NEBULA_CF_DEPTH
}  // namespace f64
}  // namespace prism::shared

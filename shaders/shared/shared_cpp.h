// C++ prelude for the dual-compiled headers in shaders/shared/.
//
// Every per-pixel formula is written once, in a *.glsl file under shaders/shared/, and compiled
// twice: by the GPU driver after prelude.glsl, and by C++ after this file, inside
// namespace prism::shared (Bruneton's functions.glsl/functions.cc scheme). GLM gives C++ the
// GLSL vector types and built-ins; the macros below cover the few places the languages differ.
// Shared files therefore use only: vec2/3/4, float literals with an f suffix, GLSL built-ins
// listed here, no swizzles, no texture functions, and these macros:
//   PRISM_INLINE  before every function (C++ needs `inline`, GLSL has no such keyword)
//   IN(T) / OUT(T) / INOUT(T)  parameter qualifiers
//   PRISM_UNUSED(x)  a parameter a variant of the file does not read (C++ warns, GLSL cannot)
//   PRISM_PRECISE  GLSL's `precise` (no fusing or reassociation) where CPU and GPU must agree
//                  bit for bit; the C++ build neither fuses (-ffp-contract=off, set by the
//                  top-level CMakeLists) nor reassociates
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#define PRISM_INLINE inline
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
#define PRISM_PRECISE
#define PRISM_UNUSED(x) static_cast<void>(x)

namespace prism::shared {
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec2 = glm::ivec2;
using mat3 = glm::mat3;
using mat4 = glm::mat4;
using glm::abs;
using glm::acos;
using glm::any;
using glm::asin;
using glm::atan;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::degrees;
using glm::dot;
using glm::exp;
using glm::exp2;
using glm::floor;
using glm::isinf;
using glm::isnan;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::radians;
using glm::sin;
using glm::smoothstep;
using glm::sqrt;

#include "constants.glsl"
}  // namespace prism::shared

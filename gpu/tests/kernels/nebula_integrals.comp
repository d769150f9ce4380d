#version 450
// Parity kernel for nebula_integrals.glsl: for in a = (u, x, λ₀, λ₁) and b = polynomial
// coefficients c₀…c₃ (c₄…c₇ = b/2): (E₁(u), ∫e^(−x/λ), ∫P·e^(−x/λ), the 4th moment on a
// basis (0, 0.2, 0.4, 0.6)).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "nebula_integrals.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer A { vec4 a[]; };
layout(std430, binding = 1) readonly buffer B { vec4 b[]; };
layout(std430, binding = 2) writeonly buffer Out { vec4 result[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  vec4 v = a[i];
  result[i] = vec4(nebulaE1(v.x), nebulaExpIntegral(v.y, v.z, v.w),
                   nebulaPolyExpIntegral(b[i], 0.5f * b[i], v.y, v.z, v.w),
                   nebulaExpMoments(v.y, vec4(0.0f, 0.2f, 0.4f, 0.6f), v.z, v.w).w);
}

#version 450
// Parity kernel for nebula_integrals.glsl's E₂…E₉: for in a = (u, half, 0, 0), E₂…E₅ (half 0)
// or E₆…E₉ (half 1) at u, every start order and both directions of the recurrence over u.
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
  vec4 lo;
  vec4 hi;
  nebulaExponentialIntegrals(a[i].x, lo, hi);
  result[i] = a[i].y > 0.5f ? hi : lo;
}

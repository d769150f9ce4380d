#version 450
// Parity kernel for nebula_integrals.glsl's negative powers: for in a = (u, x, λ₀, λ₁) and b =
// a cubic's coefficients c₀…c₃: (∫λ⁻⁵·Q·e^(−y/λ) with y = 10x, the same with y = 10x + 0.29
// (a 50 000 K Wien star's B), ∫λ⁻⁵·e^(−y/λ), ∫λ⁻²·e^(−y/λ)).
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
  float y = 10.0f * v.y;
  vec4 powers = nebulaInversePowerExpIntegrals(y, v.z, v.w);
  result[i] = vec4(nebulaWienPolyIntegral(b[i], y, v.z, v.w), nebulaWienPolyIntegral(b[i], y + 0.29f, v.z, v.w),
                   powers.x, powers.w);
}

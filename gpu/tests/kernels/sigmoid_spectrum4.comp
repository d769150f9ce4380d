#version 450
// Parity kernel for sigmoid.glsl: SPECTRUM4(coeffs[i], lambdaNm[i]) (coeffs.w unused), SPECTRUM4
// one of sigmoidSpectrum4, upsampledReflectance4 (a define set by the test).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "sigmoid.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Coeffs { vec4 coeffs[]; };
layout(std430, binding = 1) readonly buffer Lambda { vec4 lambdaNm[]; };
layout(std430, binding = 2) writeonly buffer Reflectance { vec4 reflectance[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  reflectance[i] = SPECTRUM4(coeffs[i].xyz, lambdaNm[i]);
}

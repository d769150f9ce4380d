#version 450
// Parity kernel for box_upsampling.glsl: boxReflectance4(rgb[i].xyz, lambdaNm[i]).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "box_upsampling.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Rgb { vec4 rgb[]; };
layout(std430, binding = 1) readonly buffer Lambda { vec4 lambdaNm[]; };
layout(std430, binding = 2) writeonly buffer Reflectance { vec4 reflectance[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  reflectance[i] = boxReflectance4(rgb[i].xyz, lambdaNm[i]);
}

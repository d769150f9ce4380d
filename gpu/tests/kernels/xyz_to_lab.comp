#version 450
// Parity kernel for cielab.glsl: xyzToLab(xyz[i], white[i]) (w components unused).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "cielab.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Xyz { vec4 xyz[]; };
layout(std430, binding = 1) readonly buffer White { vec4 white[]; };
layout(std430, binding = 2) writeonly buffer Lab { vec4 lab[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  lab[i] = vec4(xyzToLab(xyz[i].xyz, white[i].xyz), 0.0f);
}

#version 450
// Parity kernel for cielab.glsl: DELTA_E(labA[i], labB[i]), DELTA_E one of deltaE76,
// deltaE94, deltaE2000 (a define set by the test).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "cielab.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer LabA { vec4 labA[]; };
layout(std430, binding = 1) readonly buffer LabB { vec4 labB[]; };
layout(std430, binding = 2) writeonly buffer Difference { float difference[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  difference[i] = DELTA_E(labA[i].xyz, labB[i].xyz);
}

#version 450
// Parity kernel for sigmoid.glsl: SIGMOID_FUNCTION(x[i]), SIGMOID_FUNCTION one of sigmoid,
// sigmoidDerivative (a define set by the test).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "sigmoid.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer X { float x[]; };
layout(std430, binding = 2) writeonly buffer Y { float y[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  y[i] = SIGMOID_FUNCTION(x[i]);
}

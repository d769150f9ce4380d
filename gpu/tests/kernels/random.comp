#version 450
// Parity kernel for random.glsl. Input (seed, index, v, -); output (pcgHash(v),
// bits of randomFloat(seed, index), bits of uintToUnitFloat(v), -): compared bit for bit.
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "random.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Arguments { uvec4 arguments[]; };
layout(std430, binding = 2) writeonly buffer Results { uvec4 results[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  uvec4 a = arguments[i];
  results[i] = uvec4(pcgHash(a.z), floatBitsToUint(randomFloat(a.x, a.y)),
                     floatBitsToUint(uintToUnitFloat(a.z)), 0u);
}

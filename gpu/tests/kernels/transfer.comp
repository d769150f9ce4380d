#version 450
// Parity kernel for transfer.glsl: the vec3 form TRANSFER3 on .xyz and the scalar form TRANSFER
// on .w, e.g. TRANSFER = srgbEncode, TRANSFER3 = srgbEncode3 (defines set by the test).
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "transfer.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Signal { vec4 signal[]; };
layout(std430, binding = 2) writeonly buffer Result { vec4 result[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  vec4 v = signal[i];
  result[i] = vec4(TRANSFER3(v.xyz), TRANSFER(v.w));
}

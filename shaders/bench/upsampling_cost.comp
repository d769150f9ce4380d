#version 450
// Per-pixel cost of an upsampling lookup: every invocation turns a hashed colour into
// coefficients through one path (UPSAMPLING_FILTERED or not) and keeps one number of it.
#include "prelude.glsl"
#include "random.glsl"
#include "upsampling.glsl"
#include "common_upsampling.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Sink { float sink[]; };
layout(binding = 0) uniform sampler3D table;
uniform int resolution;
uniform uint count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  vec3 rgb = vec3(randomFloat(i, 0u), randomFloat(i, 1u), randomFloat(i, 2u));
#ifdef UPSAMPLING_FILTERED
  vec3 c = upsamplingCoefficientsFiltered(table, resolution, rgb);
#else
  vec3 c = upsamplingCoefficientsManual(table, resolution, rgb);
#endif
  sink[i] = c.x + c.y + c.z;
}

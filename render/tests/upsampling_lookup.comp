#version 450
// Both run-time lookups of shaders/common_upsampling.glsl over a list of colours.
#include "prelude.glsl"
#include "upsampling.glsl"
#include "common_upsampling.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 rgb[]; };
layout(std430, binding = 1) writeonly buffer Manual { vec4 manual[]; };
layout(std430, binding = 2) writeonly buffer Filtered { vec4 filtered[]; };
layout(binding = 0) uniform sampler3D table;
uniform int resolution;
uniform uint count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  manual[i] = vec4(upsamplingCoefficientsManual(table, resolution, rgb[i].xyz), 0.0);
  filtered[i] = vec4(upsamplingCoefficientsFiltered(table, resolution, rgb[i].xyz), 0.0);
}

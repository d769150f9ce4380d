#version 450
// Parity kernel for spherical_harmonics.glsl and prt.glsl. Input a: one direction (.xyz) per
// invocation; input b: the environment L̃ (16 × 25 floats) then the reflectance R̂ (16 vec4, .xyz).
// Output per invocation: the 25 basis functions at the direction, then, with the transfer
// T = shClampedCosine(direction) and m = 1 + i mod 16, prtXyz(prtVertexIrradiance(L̃, T, m), R̂, m)
// and Ê_{m−1} — 29 floats.
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "spherical_harmonics.glsl"
#include "prt.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Directions { vec4 directions[]; };
layout(std430, binding = 1) readonly buffer Scene { float scene[]; };
layout(std430, binding = 2) writeonly buffer Results { float results[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  vec3 dir = directions[i].xyz;
  Sh25 y = shEvaluate(dir);
  for (int k = 0; k < kShCoefficients; ++k) results[29u * i + uint(k)] = y.c[k];

  PrtEnvironment environment;
  PrtReflectance reflectance;
  for (int j = 0; j < kPrtMaxBasis; ++j) {
    for (int k = 0; k < kShCoefficients; ++k) environment.basis[j].c[k] = scene[25 * j + k];
    reflectance.r[j] = vec3(scene[400 + 4 * j], scene[401 + 4 * j], scene[402 + 4 * j]);
  }
  int m = 1 + int(i % 16u);
  PrtBasisIrradiance e = prtVertexIrradiance(environment, shClampedCosine(dir), m);
  vec3 xyz = prtXyz(e, reflectance, m);
  results[29u * i + 25u] = xyz.x;
  results[29u * i + 26u] = xyz.y;
  results[29u * i + 27u] = xyz.z;
  results[29u * i + 28u] = e.e[m - 1];
}

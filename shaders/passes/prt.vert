#version 450
// PRT forward pass, per vertex (techniques/prt/gpu/prt_pass.h): the vertex's irradiance in the
// spectral basis, Ê_j = Σ_k L̃_jk T̃_k (shared/prt.glsl's prtVertexIrradiance), interpolated as
// PRISM_PRT_BASIS_COUNT varyings. Positions are world space, drawn over the G-buffer's depth of
// the same triangles: gl_Position as gbuffer.vert computes it, invariant.
#include "shared/prelude.glsl"
#include "shared/spherical_harmonics.glsl"
#include "shared/prt.glsl"

#ifndef PRISM_PRT_BASIS_COUNT
#error "PRISM_PRT_BASIS_COUNT (1..16) must be defined"
#endif

layout(location = 0) in vec3 aPosition;
layout(location = 1) in uint aMaterial;
layout(location = 2) in vec2 aUv;
layout(std430, binding = kPrtTransferBinding) readonly buffer Transfers { Sh25 transfers[]; };
layout(std430, binding = kPrtEnvironmentBinding) readonly buffer Environment { PrtEnvironment environment; };
uniform mat4 uViewProjection;
out float vIrradiance[PRISM_PRT_BASIS_COUNT];
flat out uint vMaterial;
out vec2 vUv;
out vec3 vPositionW;  // for a medium's path and depth (prt_medium.glsl)
invariant gl_Position;

void main() {
  PrtBasisIrradiance e = prtVertexIrradiance(environment, transfers[gl_VertexID], PRISM_PRT_BASIS_COUNT);
  for (int j = 0; j < PRISM_PRT_BASIS_COUNT; ++j) vIrradiance[j] = e.e[j];
  vMaterial = aMaterial;
  vUv = aUv;
  vPositionW = aPosition;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}

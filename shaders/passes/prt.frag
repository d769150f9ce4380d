#version 450
// PRT forward pass, per fragment (techniques/prt/gpu/prt_pass.h): tristimulus = Σ_j Ê_j R̂_j
// (shared/prt.glsl's prtXyz) over the interpolated irradiance, added to the accumulation with
// alpha 0 (the lighting pass counted the frame; it left this pixel black).
#include "shared/prelude.glsl"
#include "shared/spherical_harmonics.glsl"
#include "shared/prt.glsl"

layout(std430, binding = kPrtMaterialsBinding) readonly buffer Materials { PrtGpuMaterial materials[]; };
in float vIrradiance[PRISM_PRT_BASIS_COUNT];
flat in uint vMaterial;
layout(location = 0) out vec4 oTristimulus;

void main() {
  PrtBasisIrradiance e;
  for (int j = 0; j < kPrtMaxBasis; ++j) e.e[j] = 0.0;
  for (int j = 0; j < PRISM_PRT_BASIS_COUNT; ++j) e.e[j] = vIrradiance[j];
  oTristimulus = vec4(prtXyz(e, prtReflectance(materials[vMaterial]), PRISM_PRT_BASIS_COUNT), 0.0);
}

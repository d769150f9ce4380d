#version 450
// PRT forward pass, per fragment (techniques/prt/gpu/prt_pass.h): tristimulus = Σ_j Ê_j R̂_j
// (shared/prt.glsl's prtXyz) over the interpolated irradiance, added to the accumulation with
// alpha 0 (the lighting pass counted the frame; it left this pixel black). R̂ is the material's,
// or for a textured material its texture's layers at the fragment's uv (filtered: R̂ is linear in
// the reflectance).
#include "shared/prelude.glsl"
#include "shared/spherical_harmonics.glsl"
#include "shared/prt.glsl"

layout(std430, binding = kPrtMaterialsBinding) readonly buffer Materials { PrtGpuMaterial materials[]; };
layout(binding = kPrtReflectanceTextureUnit) uniform sampler2DArray uReflectanceTexture;
uniform int uTextured;  // 1: R̂ from uReflectanceTexture
in float vIrradiance[PRISM_PRT_BASIS_COUNT];
flat in uint vMaterial;
in vec2 vUv;
layout(location = 0) out vec4 oTristimulus;

void main() {
  PrtBasisIrradiance e;
  for (int j = 0; j < kPrtMaxBasis; ++j) e.e[j] = 0.0;
  for (int j = 0; j < PRISM_PRT_BASIS_COUNT; ++j) e.e[j] = vIrradiance[j];
  PrtReflectance r;
  if (uTextured != 0) {
    for (int j = 0; j < kPrtMaxBasis; ++j) r.r[j] = vec3(0.0);
    for (int j = 0; j < PRISM_PRT_BASIS_COUNT; ++j) r.r[j] = texture(uReflectanceTexture, vec3(vUv, float(j))).rgb;
  } else {
    r = prtReflectance(materials[vMaterial]);
  }
  oTristimulus = vec4(prtXyz(e, r, PRISM_PRT_BASIS_COUNT), 0.0);
}

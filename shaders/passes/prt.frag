#version 450
// PRT forward pass, per fragment (techniques/prt/gpu/prt_pass.h): tristimulus = Σ_j Ê_j R̂_j
// (shared/prt.glsl's prtXyz) over the interpolated irradiance, clamped at 0 (prtShownXyz), added to the accumulation with
// alpha 0 (the lighting pass counted the frame; it left this pixel black). R̂ is the material's,
// or for a textured material its texture's layers at the fragment's uv (filtered: R̂ is linear in
// the reflectance). Inside the scene's medium (the water) or behind its nebula the sum runs over
// the projection's wavelength nodes, each dimmed by its transmittance (shared/prt_medium.glsl),
// with an untextured material's exact reflectance per node.
#include "shared/prelude.glsl"
#include "shared/spherical_harmonics.glsl"
#include "shared/prt.glsl"
#include "shared/prt_medium.glsl"
#ifdef PRISM_TECHNIQUE_NEBULA
#include "common_nebula_lighting.glsl"  // nebulaOpticalDepthAt: the renderer binds it for forward passes too
#endif

layout(std430, binding = kPrtMaterialsBinding) readonly buffer Materials { PrtGpuMaterial materials[]; };
layout(binding = kPrtReflectanceTextureUnit) uniform sampler2DArray uReflectanceTexture;
layout(std430, binding = kPrtMediumNodesBinding) readonly buffer MediumNodes { PrtMediumNode mediumNodes[]; };
layout(std430, binding = kPrtNodeReflectancesBinding) readonly buffer NodeReflectances { vec4 nodeReflectances[]; };
uniform int uTextured;  // 1: R̂ from uReflectanceTexture
uniform int uMediumNodeCount;
uniform int uMediumBox;  // 1: the scene has a medium in [uMediumBoxMin, uMediumBoxMax]
uniform vec3 uMediumBoxMin;
uniform vec3 uMediumBoxMax;
uniform vec3 uCameraPositionW;
uniform vec2 uFrameSize;  // pixels
in float vIrradiance[PRISM_PRT_BASIS_COUNT];
flat in uint vMaterial;
in vec2 vUv;
in vec3 vPositionW;
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
  float path = uMediumBox == 0 ? 0.0 : prtMediumViewPath(uCameraPositionW, vPositionW, uMediumBoxMin, uMediumBoxMax);
  float depth = uMediumBox == 0 ? 0.0 : prtMediumDepth(vPositionW, uMediumBoxMin, uMediumBoxMax);
#ifdef PRISM_TECHNIQUE_NEBULA
  float nebulaDepthUm = nebulaOpticalDepthAt(gl_FragCoord.xy / uFrameSize);
#else
  float nebulaDepthUm = 0.0;
#endif
  if (path == 0.0 && depth == 0.0 && nebulaDepthUm <= 0.0) {  // nothing dims: the node sum is prtXyz (prt_medium.glsl)
    oTristimulus = vec4(prtShownXyz(prtXyz(e, r, PRISM_PRT_BASIS_COUNT)), 0.0);
    return;
  }
  vec3 xyz = vec3(0.0);
  for (int q = 0; q < uMediumNodeCount; ++q) {
    PrtMediumNode node = mediumNodes[q];
    vec3 rho = uTextured != 0 ? prtNodeReflectance(r, PRISM_PRT_BASIS_COUNT, node)
                              : nodeReflectances[int(vMaterial) * uMediumNodeCount + q].xyz;
    xyz += prtMediumTransmittance(node, path, depth, nebulaDepthUm) * prtNodeIrradiance(e, PRISM_PRT_BASIS_COUNT, node) * rho;
  }
  oTristimulus = vec4(prtShownXyz(xyz), 0.0);
}

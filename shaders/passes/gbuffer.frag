#version 450
// G-buffer pass: the material's inputs at each visible point (shared/surface_inputs.glsl), as RGB
// (the albedo stays RGB here and is upsampled once per pixel in the lighting pass). Base colour
// and emissive textures are sRGB-format textures, decoded by the sampler with the sRGB transfer
// function. The emission (factor × texture) is stored for the lighting pass, which gives it the
// material's luminance and upsamples it as a light's colour.
// With PRISM_GBUFFER_COEFFICIENTS it also stores the albedo's Jakob–Hanika coefficients.
in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec4 vTangent;

#include "shared/prelude.glsl"
#include "shared/surface_inputs.glsl"
#ifdef PRISM_GBUFFER_COEFFICIENTS
#include "shared/upsampling.glsl"
#include "common_upsampling.glsl"
layout(binding = 3) uniform sampler3D uUpsamplingTable;
uniform int uUpsamplingResolution;
uniform int uFilteredLookup;
layout(location = 4) out vec4 gCoefficients;  // Jakob–Hanika c0, c1, c2 of the albedo
#endif

layout(binding = 0) uniform sampler2D uBaseColourTexture;
layout(binding = 1) uniform sampler2D uMetallicRoughnessTexture;
layout(binding = 2) uniform sampler2D uNormalTexture;
layout(binding = 4) uniform sampler2D uEmissiveTexture;
uniform vec3 uBaseColour;
uniform float uMetallic;
uniform float uRoughness;
uniform vec3 uEmissiveFactor;
uniform uint uMaterialId;  // material index + 1, with kTechniqueShadedBit for a technique's object
uniform int uTextures;     // kTexture* bits

layout(location = 0) out vec4 gAlbedoMetallic;
layout(location = 1) out vec4 gNormalRoughness;
layout(location = 2) out uint gMaterialId;
layout(location = 3) out vec4 gEmission;

void main() {
  // A zero interpolated normal (degenerate mesh) would normalise to NaN, and a NaN in the
  // accumulation would stay until it restarts: fall back to the face's own normal.
  vec3 n = dot(vNormal, vNormal) > 1e-20 ? normalize(vNormal)
                                        : normalize(cross(dFdx(vPosition), dFdy(vPosition)));
  if (!gl_FrontFacing) n = -n;
  vec3 baseColourTexel = (uTextures & kTextureBaseColour) != 0
                             ? texture(uBaseColourTexture, vUv).rgb : vec3(1.0);
  vec4 metallicRoughnessTexel = (uTextures & kTextureMetallicRoughness) != 0
                                    ? texture(uMetallicRoughnessTexture, vUv) : vec4(1.0);
  vec3 normalTexel = (uTextures & kTextureNormal) != 0 ? texture(uNormalTexture, vUv).xyz
                                                       : vec3(0.5, 0.5, 1.0);
  vec3 emissiveTexel = (uTextures & kTextureEmission) != 0 ? texture(uEmissiveTexture, vUv).rgb : vec3(1.0);
  SurfaceInputs s = surfaceInputs(uBaseColour, uMetallic, uRoughness, n, vTangent, uTextures,
                                  baseColourTexel, metallicRoughnessTexel, normalTexel, uEmissiveFactor,
                                  emissiveTexel);
  gAlbedoMetallic = vec4(s.albedo, s.metallic);
  gNormalRoughness = vec4(s.normal, s.roughness);
  gMaterialId = uMaterialId;
  gEmission = vec4(s.emission, 0.0);
#ifdef PRISM_GBUFFER_COEFFICIENTS
  gCoefficients = vec4(uFilteredLookup != 0
                           ? upsamplingCoefficientsFiltered(uUpsamplingTable, uUpsamplingResolution, s.albedo)
                           : upsamplingCoefficientsManual(uUpsamplingTable, uUpsamplingResolution, s.albedo),
                       0.0);
#endif
}

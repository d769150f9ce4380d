#version 450
// Spectral lighting pass: shaders/shared/pixel_shading.glsl for every pixel, over the G-buffer,
// with this frame's constants in a uniform block and its data in shader storage buffers (layout:
// shared/frame_layout.glsl, both written once for GLSL and C++). Writes
// tristimulus with alpha 1 into an accumulation target blended additively, so that after N
// frames rgb / a is the mean of N frames (temporal accumulation of stochastic wavelengths).
#include "shared/prelude.glsl"
#include "shared/sigmoid.glsl"
#include "shared/box_upsampling.glsl"
#include "shared/upsampling.glsl"
#include "shared/brdf.glsl"
#include "shared/lights.glsl"
#include "shared/shadow_filter.glsl"
#include "shared/frame_layout.glsl"
#include "common_upsampling.glsl"

layout(std140, binding = kFrameConstantsBinding) uniform Frame { FrameConstants frame; };
layout(std430, binding = 0) readonly buffer Batches { GpuBatch batches[]; };
layout(std430, binding = 1) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = 2) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = 3) readonly buffer LightSpectra { vec4 lightSpectra[]; };
layout(std430, binding = 4) readonly buffer MaterialSpectra { vec4 materialSpectra[]; };

layout(binding = 0) uniform sampler2D gAlbedoMetallic;
layout(binding = 1) uniform sampler2D gNormalRoughness;
layout(binding = 2) uniform usampler2D gMaterialId;
layout(binding = 3) uniform sampler2D gDepth;
layout(binding = 4) uniform sampler2DArray uShadowMaps;
layout(binding = 5) uniform sampler3D uUpsamplingTable;
layout(binding = 6) uniform sampler2D gCoefficients;  // read when frame.gbufferCoefficients != 0
layout(binding = 13) uniform sampler2D gEmission;  // PRISM_RGB_EMISSION; 7–12 are the techniques'

layout(location = 0) out vec4 oTristimulus;

GpuBatch frameBatch(int b) { return batches[b]; }
GpuLight frameLight(int l) { return lights[l]; }
GpuMaterial frameMaterial(int id) { return materials[id]; }
vec4 frameLightSpectrum(int l, int b) { return lightSpectra[lightSpectrumIndex(l, b, frame.batchCount)]; }
vec4 frameMaterialSpectrum(int s, int b, int j) {
  return materialSpectra[materialSpectrumIndex(s, b, j, frame.batchCount)];
}
// Each technique's block, tables and accessors (its common_<name>_lighting.glsl, bindings from its
// shared header).
#ifdef PRISM_TECHNIQUE_WATER
#include "common_water_lighting.glsl"
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
#include "common_sky_lighting.glsl"
#endif
#ifdef PRISM_TECHNIQUE_NEBULA
#include "common_nebula_lighting.glsl"
#endif

float shadowDepthAt(int layer, int x, int y) {
  return texelFetch(uShadowMaps, ivec3(x, y, layer), 0).r;
}
vec3 upsamplingCoefficients(vec3 rgb) {
  if (frame.gbufferCoefficients != 0) return texelFetch(gCoefficients, ivec2(gl_FragCoord.xy), 0).xyz;
  return frame.filteredLookup != 0
             ? upsamplingCoefficientsFiltered(uUpsamplingTable, frame.upsamplingResolution, rgb)
             : upsamplingCoefficientsManual(uUpsamplingTable, frame.upsamplingResolution, rgb);
}
vec3 emissionCoefficients(vec3 rgb) {
  return upsamplingCoefficientsManual(uUpsamplingTable, frame.upsamplingResolution, rgb);
}

#include "shared/pixel_shading.glsl"

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uint id = texelFetch(gMaterialId, p, 0).r;
  if (id == 0u) {
    // No geometry: the far plane through this pixel, reconstructed from depth 1.
    vec3 farPoint = worldFromDepth(frame.inverseViewProjection, (vec2(p) + 0.5) / frame.viewportSize, 1.0);
    oTristimulus = vec4(shadeBackground(frame, farPoint, frame.cameraPositionW, (vec2(p) + 0.5) / frame.viewportSize), 1.0);
    return;
  }
  vec4 am = texelFetch(gAlbedoMetallic, p, 0);
  vec4 nr = texelFetch(gNormalRoughness, p, 0);
  SurfaceSample s;
  s.position = worldFromDepth(frame.inverseViewProjection, (vec2(p) + 0.5) / frame.viewportSize,
                              texelFetch(gDepth, p, 0).r);
  s.normal = normalize(nr.xyz);
  s.albedo = am.rgb;
#ifdef PRISM_RGB_EMISSION
  s.emission = texelFetch(gEmission, p, 0).rgb;
#else
  s.emission = vec3(0.0);  // the target is not drawn: what it holds is another scene's
#endif
  s.metallic = am.a;
  s.roughness = nr.a;
  s.material = int(id & ~kTechniqueShadedBit) - 1;
  s.techniqueShaded = (id & kTechniqueShadedBit) != 0u;
  oTristimulus = vec4(shadeSurface(frame, s, frame.cameraPositionW, (vec2(p) + 0.5) / frame.viewportSize), 1.0);
}

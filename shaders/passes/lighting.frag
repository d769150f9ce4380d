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
#ifdef PRISM_TECHNIQUE_WATER
#include "shared/underwater.glsl"
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
#include "shared/atmosphere_model.glsl"
#endif
#include "common_upsampling.glsl"

layout(std140, binding = kFrameConstantsBinding) uniform Frame { FrameConstants frame; };
layout(std430, binding = 0) readonly buffer Batches { GpuBatch batches[]; };
layout(std430, binding = 1) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = 2) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = 3) readonly buffer LightSpectra { vec4 lightSpectra[]; };
layout(std430, binding = 4) readonly buffer MaterialSpectra { vec4 materialSpectra[]; };
// Each technique's block, where its shared header says.
#ifdef PRISM_TECHNIQUE_WATER
layout(std140, binding = kWaterConstantsBinding) uniform Water { WaterConstants water; };
layout(std430, binding = kWaterSpectraBinding) readonly buffer WaterSpectra { vec4 waterSpectra[]; };
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
layout(std140, binding = kSkyConstantsBinding) uniform Sky { SkyConstants sky; };
layout(std430, binding = kSkyAtmospheresBinding) readonly buffer Atmospheres { GpuAtmosphere atmospheres[]; };
layout(std430, binding = 7) readonly buffer SkyIrradiance { vec4 skyIrradianceSh[]; };
#endif

layout(binding = 0) uniform sampler2D gAlbedoMetallic;
layout(binding = 1) uniform sampler2D gNormalRoughness;
layout(binding = 2) uniform usampler2D gMaterialId;
layout(binding = 3) uniform sampler2D gDepth;
layout(binding = 4) uniform sampler2DArray uShadowMaps;
layout(binding = 5) uniform sampler3D uUpsamplingTable;
layout(binding = 6) uniform sampler2D gCoefficients;  // read when frame.gbufferCoefficients != 0
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
// The sky's tables (render/atmosphere_pass.h).
layout(binding = 7) uniform sampler2DArray uTransmittanceLut;
layout(binding = 8) uniform sampler2DArray uMultipleScatteringLut;
layout(binding = 9) uniform sampler2DArray uSkyViewLut;
layout(binding = 10) uniform sampler2DArray uAerialPerspective;
#endif

layout(location = 0) out vec4 oTristimulus;

GpuBatch frameBatch(int b) { return batches[b]; }
GpuLight frameLight(int l) { return lights[l]; }
GpuMaterial frameMaterial(int id) { return materials[id]; }
vec4 frameLightSpectrum(int l, int b) { return lightSpectra[lightSpectrumIndex(l, b, frame.batchCount)]; }
vec4 frameMaterialSpectrum(int s, int b, int j) {
  return materialSpectra[materialSpectrumIndex(s, b, j, frame.batchCount)];
}
#ifdef PRISM_TECHNIQUE_WATER
WaterConstants frameWater() { return water; }
vec4 frameWaterSpectrum(int b, int j) { return waterSpectra[waterSpectrumIndex(b, j)]; }
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
SkyConstants frameSky() { return sky; }
GpuAtmosphere frameAtmosphere(int b) { return atmospheres[b]; }
vec4 transmittanceLutTexel(int b, int x, int y) { return texelFetch(uTransmittanceLut, ivec3(x, y, b), 0); }
vec4 multipleScatteringLutTexel(int b, int x, int y) {
  return texelFetch(uMultipleScatteringLut, ivec3(x, y, b), 0);
}
vec4 skyViewLutTexel(int b, int x, int y) { return texelFetch(uSkyViewLut, ivec3(x, y, b), 0); }
vec4 aerialPerspectiveTexel(int b, int x, int y, int slice, int j) {
  return texelFetch(uAerialPerspective, ivec3(b * kAerialPerspectiveSize + x, y, j * kAerialPerspectiveSlices + slice), 0);
}
vec4 skyIrradianceCoefficient(int b, int k) { return skyIrradianceSh[b * 4 + k]; }
#include "shared/atmosphere_luts.glsl"
#include "shared/atmosphere_lighting.glsl"
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

#include "shared/pixel_shading.glsl"

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uint id = texelFetch(gMaterialId, p, 0).r;
  if (id == 0u) {
    // No geometry: the far plane through this pixel, reconstructed from depth 1.
    vec3 farPoint = worldFromDepth(frame.inverseViewProjection, (vec2(p) + 0.5) / frame.viewportSize, 1.0);
    oTristimulus = vec4(shadeBackground(frame, farPoint, frame.cameraPositionW), 1.0);
    return;
  }
  vec4 am = texelFetch(gAlbedoMetallic, p, 0);
  vec4 nr = texelFetch(gNormalRoughness, p, 0);
  SurfaceSample s;
  s.position = worldFromDepth(frame.inverseViewProjection, (vec2(p) + 0.5) / frame.viewportSize,
                              texelFetch(gDepth, p, 0).r);
  s.normal = normalize(nr.xyz);
  s.albedo = am.rgb;
  s.metallic = am.a;
  s.roughness = nr.a;
  s.material = int(id) - 1;
  oTristimulus = vec4(shadeSurface(frame, s, frame.cameraPositionW, (vec2(p) + 0.5) / frame.viewportSize), 1.0);
}

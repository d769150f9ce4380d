// The lighting pass's side of the nebula (techniques/nebula): the optical depth its march left
// (techniques/nebula/gpu/nebula_pass.h, bindForLighting), the star depths it marched with, and the
// section's block of star lights, at the units and bindings shared/nebula_lighting.glsl declares,
// and the accessors shared/pixel_shading.glsl reads them through.
#include "shared/nebula_march.glsl"
#include "shared/nebula_lighting.glsl"
#include "common_nebula_fields.glsl"

layout(binding = kNebulaOpticalDepthUnit) uniform sampler2D uNebulaOpticalDepth;
// RGBA32F, nx × ny × (nz · ⌈stars/4⌉): star s's depth g_s (µm) in lane s % 4 of slab s / 4.
layout(binding = kNebulaStarDepthUnit) uniform sampler3D uNebulaStarDepth;
layout(std140, binding = kNebulaLightConstantsBinding) uniform NebulaLight { NebulaLightConstants nebulaLight; };
layout(std430, binding = kNebulaStarLightsBinding) readonly buffer NebulaStarLights { vec4 nebulaStarLights[]; };

float nebulaOpticalDepthAt(vec2 uv) {
  return texelFetch(uNebulaOpticalDepth, ivec2(uv * vec2(textureSize(uNebulaOpticalDepth, 0))), 0).r;
}

NebulaLightConstants frameNebula() { return nebulaLight; }
vec4 nebulaStarData(int i) { return nebulaStarLights[i]; }

float nebulaStarDepthAt(int star, vec3 pCube) {
  ivec3 size = textureSize(uNebulaStarDepth, 0);
  int nz = nebulaLight.voxelsZ;
  return fieldOf(uNebulaStarDepth, cellAt(pCube, ivec3(size.x, size.y, nz)), star / 4, nz)[star % 4];
}

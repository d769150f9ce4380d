// The lighting pass's side of the nebula (techniques/nebula): the optical depth its march left
// (techniques/nebula/gpu/nebula_pass.h, bindForLighting), at the unit shared/nebula_lighting.glsl
// declares, and the accessor shared/pixel_shading.glsl reads it through.
#include "shared/nebula_lighting.glsl"

layout(binding = kNebulaOpticalDepthUnit) uniform sampler2D uNebulaOpticalDepth;

float nebulaOpticalDepthAt(vec2 uv) {
  return texelFetch(uNebulaOpticalDepth, ivec2(uv * vec2(textureSize(uNebulaOpticalDepth, 0))), 0).r;
}

// The lighting pass's side of the sky (techniques/atmosphere): its block, at the bindings
// shared/atmosphere_model.glsl declares, the tables of its pass (techniques/atmosphere/gpu/
// atmosphere_pass.h, bindForLighting), and the accessors shared/pixel_shading.glsl and the
// sky's shared files read them through.
#include "shared/atmosphere_model.glsl"

layout(std140, binding = kSkyConstantsBinding) uniform Sky { SkyConstants sky; };
layout(std430, binding = kSkyAtmospheresBinding) readonly buffer Atmospheres { GpuAtmosphere atmospheres[]; };
layout(std430, binding = 7) readonly buffer SkyIrradiance { vec4 skyIrradianceSh[]; };
layout(binding = 7) uniform sampler2DArray uTransmittanceLut;
layout(binding = 8) uniform sampler2DArray uMultipleScatteringLut;
layout(binding = 9) uniform sampler2DArray uSkyViewLut;
layout(binding = 10) uniform sampler2DArray uAerialPerspective;

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

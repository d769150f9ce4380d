// The atmosphere compute passes' side of shaders/shared/atmosphere_luts.glsl: one GpuAtmosphere
// per batch in a storage buffer, and the tables of earlier passes as texture arrays (layer =
// batch) read texel by texel (the shared code interpolates itself, as the CPU does).
layout(std430, binding = 0) readonly buffer Atmospheres { GpuAtmosphere atmospheres[]; };
layout(binding = 0) uniform sampler2DArray uTransmittanceLut;
layout(binding = 1) uniform sampler2DArray uMultipleScatteringLut;
layout(binding = 2) uniform sampler2DArray uSkyViewLut;

vec4 transmittanceLutTexel(int b, int x, int y) {
  return texelFetch(uTransmittanceLut, ivec3(x, y, b), 0);
}
vec4 multipleScatteringLutTexel(int b, int x, int y) {
  return texelFetch(uMultipleScatteringLut, ivec3(x, y, b), 0);
}
vec4 skyViewLutTexel(int b, int x, int y) { return texelFetch(uSkyViewLut, ivec3(x, y, b), 0); }

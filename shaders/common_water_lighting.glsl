// The lighting pass's side of the water (techniques/underwater): its block, at the bindings
// shared/underwater.glsl declares, the lamps' in-scattering, and the accessors
// shared/pixel_shading.glsl reads the block through.
#include "shared/underwater.glsl"
#include "shared/underwater_lamps.glsl"

layout(std140, binding = kWaterConstantsBinding) uniform Water { WaterConstants water; };
layout(std430, binding = kWaterSpectraBinding) readonly buffer WaterSpectra { vec4 waterSpectra[]; };

WaterConstants frameWater() { return water; }
vec4 frameWaterSpectrum(int b, int j) { return waterSpectra[waterSpectrumIndex(b, j)]; }

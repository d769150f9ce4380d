#version 450
// The transmittance table without its wavelengths (shared/atmosphere_luts.glsl,
// unitCoefficientAtmosphere): per (r, μ) texel the optical depths of Rayleigh, Mie and ozone at
// unit coefficients, integrated once a frame for every batch (all batches of the frame share the
// atmosphere's shape).
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/prelude.glsl"
#include "shared/atmosphere_model.glsl"
#include "common_atmosphere.glsl"
#include "shared/atmosphere_luts.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray uOut;  // one layer

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x >= kTransmittanceLutWidth || id.y >= kTransmittanceLutHeight) return;
  imageStore(uOut, ivec3(id, 0), transmittanceLutValue(unitCoefficientAtmosphere(atmospheres[0]), id.x, id.y));
}

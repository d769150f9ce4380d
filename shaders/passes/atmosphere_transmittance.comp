#version 450
// Hillaire's transmittance table, one layer per batch: optical depth to the top of the
// atmosphere per (r, μ) texel, each batch's coefficients times the constituents' optical depths
// (atmosphere_transmittance_densities.comp; shared/atmosphere_luts.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/prelude.glsl"
#include "shared/atmosphere_model.glsl"
#include "common_atmosphere.glsl"
#include "shared/atmosphere_luts.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray uOut;
layout(rgba32f, binding = 1) uniform readonly image2DArray uDensities;  // one layer

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (id.x >= kTransmittanceLutWidth || id.y >= kTransmittanceLutHeight) return;
  imageStore(uOut, id, transmittanceFromDensities(atmospheres[id.z], imageLoad(uDensities, ivec3(id.xy, 0))));
}

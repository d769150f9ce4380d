#version 450
// Hillaire's multiple-scattering table Ψ_ms per (μ_s, r), one layer per batch; reads the
// transmittance table (shared/atmosphere_luts.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/prelude.glsl"
#include "shared/atmosphere_model.glsl"
#include "common_atmosphere.glsl"
#include "shared/atmosphere_luts.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray uOut;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (id.x >= kMultipleScatteringLutSize || id.y >= kMultipleScatteringLutSize) return;
  imageStore(uOut, id, multipleScatteringLutValue(atmospheres[id.z], id.z, id.x, id.y));
}

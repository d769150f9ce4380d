#version 450
// Hillaire's sky-view table seen from the camera's radius under this frame's sun, one layer
// per batch; reads the transmittance and multiple-scattering tables (shared/atmosphere_luts.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/prelude.glsl"
#include "shared/atmosphere_model.glsl"
#include "common_atmosphere.glsl"
#include "shared/atmosphere_luts.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray uOut;
uniform float uCameraRadiusKm;
uniform float uMuSun;  // the sun's zenith cosine at the camera

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (id.x >= kSkyViewLutWidth || id.y >= kSkyViewLutHeight) return;
  imageStore(uOut, id, skyViewLutValue(atmospheres[id.z], id.z, uCameraRadiusKm, uMuSun, id.x, id.y));
}

#version 450
// The aerial-perspective volume: per froxel column of the screen and batch, in-scattering and
// transmittance at the end of each of the 32 depth slices (shared/atmosphere_luts.glsl's
// aerialPerspectiveSlice). One texture array, batch b at x = b·32 + column, layer j·32 + slice
// (j 0: in-scattering, solar irradiance applied; 1: transmittance): batches side by side keep
// the layer count at 64 however many batches a frame has (a layer per batch and slice would
// pass GL 4.5's guaranteed 2048 layers at the reference's 118 batches); the width, 32 per
// batch, stays within 16384 up to 512 batches.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/prelude.glsl"
#include "shared/atmosphere_model.glsl"
#include "common_atmosphere.glsl"
#include "shared/atmosphere_luts.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray uOut;
uniform mat4 uInverseViewProjection;
uniform vec3 uCameraWorld;    // metres
uniform float uOriginKm;      // planet radius + the ground's altitude
uniform vec3 uSun;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (id.x >= kAerialPerspectiveSize || id.y >= kAerialPerspectiveSize) return;
  vec2 uv = vec2(id.xy) / float(kAerialPerspectiveSize - 1);
  vec4 far = uInverseViewProjection * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
  vec3 direction = normalize(far.xyz / far.w - uCameraWorld);
  vec3 camera = vec3(uCameraWorld.x * 1e-3, uOriginKm + uCameraWorld.y * 1e-3, uCameraWorld.z * 1e-3);
  GpuAtmosphere a = atmospheres[id.z];
  ScatteringIntegral acc = emptyScatteringIntegral();
  for (int k = 0; k < kAerialPerspectiveSlices; ++k) {
    aerialPerspectiveSlice(a, id.z, camera, direction, uSun, k, acc);
    ivec2 texel = ivec2(id.z * kAerialPerspectiveSize + id.x, id.y);
    imageStore(uOut, ivec3(texel, k), acc.radiance * a.solarIrradiance);
    imageStore(uOut, ivec3(texel, kAerialPerspectiveSlices + k), acc.transmittance);
  }
}

#version 450
// The sky's irradiance as four spherical-harmonic coefficients per batch, from the sky-view
// table (shared/atmosphere_lighting.glsl): one invocation per (coefficient, batch).
layout(local_size_x = 4) in;
#include "shared/prelude.glsl"
#include "shared/atmosphere_model.glsl"
#include "common_atmosphere.glsl"
#include "shared/atmosphere_luts.glsl"

vec4 aerialPerspectiveTexel(int b, int x, int y, int slice, int j) { return vec4(0.0); }
vec4 skyIrradianceCoefficient(int b, int k) { return vec4(0.0); }
#include "shared/atmosphere_lighting.glsl"

layout(std430, binding = 1) writeonly buffer SkyIrradiance { vec4 skyIrradianceOut[]; };
uniform float uCameraRadiusKm;
uniform vec3 uSun;  // unit, towards the sun

void main() {
  int k = int(gl_GlobalInvocationID.x), b = int(gl_GlobalInvocationID.y);
  skyIrradianceOut[b * 4 + k] = skyIrradianceCoefficientValue(atmospheres[b], b, uCameraRadiusKm, uSun, k);
}

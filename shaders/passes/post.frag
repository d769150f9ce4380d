#version 450
// Post pass: the accumulated tristimulus (mean of the frames so far) → exposure → display RGB
// (white balance and, for a camera observer, the camera matrix folded into one 3×3) → gamut
// compression → tone map → the light's hue kept → the display's transfer function → dither →
// 8-bit target.
#include "shared/prelude.glsl"
#include "shared/transfer.glsl"
#include "shared/cielab.glsl"
#include "shared/random.glsl"
#include "shared/post.glsl"

layout(binding = 0) uniform sampler2D uAccumulation;
uniform mat3 uToDisplay;          // tristimulus → linear display RGB, exposure included
uniform mat3 uDisplayToXyz;       // the display's primaries: linear RGB → XYZ (white Y = 1)
uniform mat3 uXyzToDisplay;       // and back
uniform int uToneMap;
uniform int uTransfer;            // 0 sRGB curve (sRGB, Display P3), 1 BT.2020
uniform int uDither;
uniform uint uSeed;

layout(location = 0) out vec4 oColour;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 acc = texelFetch(uAccumulation, p, 0);
  vec3 tristimulus = acc.a > 0.0 ? acc.rgb / acc.a : vec3(0.0);
  vec3 rgb = encodeForDisplay(uToDisplay, uDisplayToXyz, uXyzToDisplay, uToneMap, uTransfer, tristimulus);
  if (uDither != 0) {
    uint seed = pcgHash(uint(p.x) + 65536u * uint(p.y)) ^ uSeed;
    rgb += vec3(ditherOffset(randomFloat(seed, 0u), randomFloat(seed, 1u)),
                ditherOffset(randomFloat(seed, 2u), randomFloat(seed, 3u)),
                ditherOffset(randomFloat(seed, 4u), randomFloat(seed, 5u)));
  }
  oColour = vec4(clamp(rgb, 0.0, 1.0), 1.0);
}

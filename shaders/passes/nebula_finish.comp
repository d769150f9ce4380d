#version 450
// Finishes the nebula's pixels from what nebula_march.comp wrote: per channel c,
//   colour_c = marched_c + Σ_l response_l,c·lineLight_l + Σ_v W[v][c]·moment_v,
// marched the direct methods' colour (0 for the others), response_l,c = P_S,c(λₗ)·wₗ the filters'
// response to line l times its weight, and v over (star, basis element) for projection (W = the
// filters' integrals of each star's light on the orthonormalised basis) or (2D element, basis
// element) for light–density. A filter change uploads new weights and responses and re-runs this
// pass alone: for projection and light–density the march does not depend on the filters. The CPU
// marcher's last loop (NebulaRenderer::render), in the same order. In 8×8 tiles of the image, as
// the march: a line of 64-pixel groups would outrun a dispatch's 65 535 groups past 2048² pixels.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 3) readonly buffer Lines { vec4 lines[]; };  // λ (µm), response per channel
layout(std430, binding = 4) readonly buffer Moments { float moments[]; };  // [v·P + pixel]
layout(std430, binding = 5) readonly buffer Marched { float marched[]; };  // [v·P + pixel]: colour, lines
layout(std430, binding = 6) readonly buffer Weights { float weights[]; };  // [(g·3 + c)·card + j]
layout(std430, binding = 7) writeonly buffer Colour { vec4 colour[]; };

uniform int uWidth;
uniform int uPixelCount;
uniform int uCount;  // stars (projection) or 2D elements (light–density); 0 for the direct methods
uniform int uCard;
uniform int uLineCount;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= uWidth || px.y * uWidth >= uPixelCount) return;
  int pixel = px.y * uWidth + px.x;
  vec3 c = vec3(marched[pixel], marched[uPixelCount + pixel], marched[2 * uPixelCount + pixel]);
  for (int l = 0; l < uLineCount; ++l) c += marched[(3 + l) * uPixelCount + pixel] * lines[l].yzw;
  for (int g = 0; g < uCount; ++g)
    for (int ch = 0; ch < 3; ++ch)
      for (int j = 0; j < uCard; ++j)
        c[ch] += weights[(g * 3 + ch) * uCard + j] * moments[(g * uCard + j) * uPixelCount + pixel];
  colour[pixel] = vec4(c, 0.0f);
}

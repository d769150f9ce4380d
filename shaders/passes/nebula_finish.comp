#version 450
// Finishes the nebula's pixels from the moments nebula_march.comp wrote: per channel c,
//   colour_c = lines_c + Σ_v W[v][c]·moment_v,
// v over (star, basis element) for projection (W = the filters' integrals of each star's light on
// the orthonormalised basis) or (2D element, basis element) for light–density. A filter change
// uploads new weights and re-runs this pass alone: the march does not depend on the filters.
// The CPU marcher's last loop (NebulaRenderer::render), in the same order.
layout(local_size_x = 64) in;

layout(std430, binding = 4) readonly buffer Moments { float moments[]; };  // [v·P + pixel]
layout(std430, binding = 5) readonly buffer LineColour { vec4 lineColour[]; };
layout(std430, binding = 6) readonly buffer Weights { float weights[]; };  // [(g·3 + c)·card + j]
layout(std430, binding = 7) writeonly buffer Colour { vec4 colour[]; };

uniform int uPixelCount;
uniform int uCount;  // stars (projection) or 2D elements (light–density)
uniform int uCard;

void main() {
  int pixel = int(gl_GlobalInvocationID.x);
  if (pixel >= uPixelCount) return;
  vec3 c = lineColour[pixel].xyz;
  for (int g = 0; g < uCount; ++g)
    for (int ch = 0; ch < 3; ++ch)
      for (int j = 0; j < uCard; ++j)
        c[ch] += weights[(g * 3 + ch) * uCard + j] * moments[(g * uCard + j) * uPixelCount + pixel];
  colour[pixel] = vec4(c, 0.0f);
}

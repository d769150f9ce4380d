#version 450
// Reads every texel of a 2D texture as a shader sees it (sRGB decoded, no filtering) into an
// SSBO, one invocation per texel, rows bottom first.
layout(local_size_x = 1) in;
layout(binding = 0) uniform sampler2D uTexture;
layout(std430, binding = 2) writeonly buffer Results { vec4 results[]; };
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  results[p.y * textureSize(uTexture, 0).x + p.x] = texelFetch(uTexture, p, 0);
}

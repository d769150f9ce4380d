#version 450
// Writes (x, y, 1, 2) into every texel of an rgba32f image bound with Texture2D::bindImage.
layout(local_size_x = 1) in;
layout(rgba32f, binding = 0) writeonly uniform image2D uImage;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  imageStore(uImage, p, vec4(vec2(p), 1.0f, 2.0f));
}

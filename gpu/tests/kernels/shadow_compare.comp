#version 450
// Depth comparisons through a sampler2DArrayShadow at the centre of each layer: result i is
// texture(uShadow, (0.5, 0.5, layer i, reference i)), 1 where reference <= depth (GL_LEQUAL).
layout(local_size_x = 1) in;
layout(binding = 0) uniform sampler2DArrayShadow uShadow;
layout(std430, binding = 0) readonly buffer References { float references[]; };
layout(std430, binding = 2) writeonly buffer Results { float results[]; };
uniform uint uCount;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  results[i] = texture(uShadow, vec4(0.5f, 0.5f, float(i), references[i]));
}

#version 450
// Echoes uniforms of every type Program::setUniform takes into an SSBO, matrices column by
// column, so that the test sees what the shader received.
layout(local_size_x = 1) in;
layout(std430, binding = 2) writeonly buffer Results { float results[]; };
uniform vec2 uV2;
uniform vec3 uV3;
uniform vec4 uV4;
uniform ivec2 uI2;
uniform mat3 uM3;
uniform mat4 uM4;
#ifdef WITH_OPTIONAL
uniform float uOptional;
#endif
void main() {
  int n = 0;
  for (int i = 0; i < 2; ++i) results[n++] = uV2[i];
  for (int i = 0; i < 3; ++i) results[n++] = uV3[i];
  for (int i = 0; i < 4; ++i) results[n++] = uV4[i];
  for (int i = 0; i < 2; ++i) results[n++] = float(uI2[i]);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) results[n++] = uM3[c][r];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) results[n++] = uM4[c][r];
#ifdef WITH_OPTIONAL
  results[n++] = uOptional;
#endif
}

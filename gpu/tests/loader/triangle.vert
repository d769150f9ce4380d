#version 450
// Loader fixture: a full-screen triangle, with the fragment stage below: a draw program links.
#include "prelude.glsl"
layout(location = 0) out vec2 uv;
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  uv = p;
  gl_Position = vec4(2.0f * p - 1.0f, 0.0f, 1.0f);
}

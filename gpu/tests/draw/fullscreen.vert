#version 450
// A triangle covering the whole viewport, made from gl_VertexID alone (draw 3 vertices from an
// attributeless VAO); uv spans [0, 1] over the viewport.
layout(location = 0) out vec2 uv;
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  uv = p;
  gl_Position = vec4(2.0f * p - 1.0f, 0.0f, 1.0f);
}

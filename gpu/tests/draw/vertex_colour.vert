#version 450
// A position and a normalised unsigned-byte colour from an interleaved vertex buffer.
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 colour;
layout(location = 0) out vec4 vColour;
void main() {
  vColour = colour;
  gl_Position = vec4(position, 0.0f, 1.0f);
}

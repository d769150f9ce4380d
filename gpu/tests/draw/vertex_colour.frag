#version 450
// The interpolated vertex colour.
layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 colour;
void main() { colour = vColour; }

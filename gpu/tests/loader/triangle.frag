#version 450
// Loader fixture: the fragment stage of triangle.vert, with a define from the test.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(uv, FRAGMENT_BLUE, 1.0f); }

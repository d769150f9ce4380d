#version 450
// Loader fixture: cycle_a.glsl -> cycle_b.glsl -> cycle_a.glsl.
#include "cycle_a.glsl"

layout(local_size_x = 1) in;
void main() {}

#version 450
// Loader fixture: includes a file that exists nowhere.
#include "prelude.glsl"
#include "does_not_exist.glsl"  // MISSING

layout(local_size_x = 1) in;
void main() {}

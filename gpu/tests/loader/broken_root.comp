#version 450
// Loader fixture: the compile error is in the included file, on its marked line.
#include "prelude.glsl"
#include "broken_body.glsl"

layout(local_size_x = 1) in;
void main() {}

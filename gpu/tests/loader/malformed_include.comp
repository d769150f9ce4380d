#version 450
// Loader fixture: system-style includes are not supported.
#include <prelude.glsl>  // MALFORMED
layout(local_size_x = 1) in;
void main() {}

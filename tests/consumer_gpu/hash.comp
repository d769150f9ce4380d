#version 450
// Consumer fixture: the installed random.glsl, through the installed loader.
#include "prelude.glsl"
#include "random.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Result { uint result[]; };
void main() { result[0] = pcgHash(0u); }

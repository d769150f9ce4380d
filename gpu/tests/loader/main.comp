#version 450
// Loader fixture: includes beside itself (lib/…), beside an included file (lib/second.glsl from
// lib/first.glsl), from an include folder (prelude.glsl), and the same file twice.
#extension GL_GOOGLE_include_directive : enable
#include "prelude.glsl"
#include "lib/first.glsl"
#include "lib/second.glsl"
#include "shadow.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = 2) writeonly buffer Result { uint result[]; };

void main() {
  result[0] = first() + SECOND_TWICE + shadow();  // 41 + 80 + 1000
}

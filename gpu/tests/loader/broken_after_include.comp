#version 450
// Loader fixture: the error is in this file, after an include, on the marked line.
#include "prelude.glsl"
#include "lib/second.glsl"

layout(local_size_x = 1) in;
void main() {
  uint value = second() + undeclaredName;  // BROKEN: undeclared identifier
}

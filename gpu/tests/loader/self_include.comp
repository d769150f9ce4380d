#version 450
// Loader fixture: includes itself.
#include "self_include.comp"  // CYCLE
layout(local_size_x = 1) in;
void main() {}

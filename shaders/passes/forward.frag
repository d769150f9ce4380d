#version 450
// Forward pass: an emissive marker added to the accumulated tristimulus (alpha 0: it does not
// count as a frame).
uniform vec3 uTristimulus;
layout(location = 0) out vec4 oTristimulus;

void main() { oTristimulus = vec4(uTristimulus, 0.0); }

#version 450
// Adds a nebula the marcher left in a buffer (nebula_finish.comp's colour, row 0 at the top) to
// the frame's tristimulus accumulation (techniques/nebula/gpu/nebula_pass.h): its three channels
// turned into the frame's tristimulus by uToTristimulus (intensity included), alpha 0 so that the
// lighting pass's frame count stays the mean's denominator.
layout(std430, binding = 7) readonly buffer Colour { vec4 colour[]; };

uniform ivec2 uSize;
uniform mat3 uToTristimulus;

out vec4 fragColour;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 c = colour[(uSize.y - 1 - p.y) * uSize.x + p.x].xyz;
  fragColour = vec4(uToTristimulus * c, 0.0f);
}

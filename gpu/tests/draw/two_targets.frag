#version 450
// Two render targets at once: a constant float colour, and an integer naming the pixel, so that
// the test sees every pixel written, in the right place, in each attachment.
layout(location = 0) out vec4 colour;
layout(location = 1) out uint pixelId;
uniform vec4 uColour;
uniform uint uIdOffset;
void main() {
  colour = uColour;
  uvec2 p = uvec2(gl_FragCoord.xy);  // pixel centres: (x + 0.5, y + 0.5)
  pixelId = uIdOffset + p.x + 1000u * p.y;
}

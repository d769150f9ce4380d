// Stand-ins for the accessors shaders/shared/atmosphere_lighting.glsl expects its includer to
// define (shaders/passes/lighting.frag has the real ones).
vec4 skyViewLutTexel(int b, int x, int y) { return vec4(b + x + y); }
vec4 aerialPerspectiveTexel(int b, int x, int y, int slice, int j) { return vec4(b + x + y + slice + j); }
vec4 skyIrradianceCoefficient(int b, int k) { return vec4(b + k); }

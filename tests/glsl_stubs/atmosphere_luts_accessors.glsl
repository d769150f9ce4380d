// Stand-ins for the accessors shaders/shared/atmosphere_luts.glsl expects its includer to define
// (shaders/common_atmosphere.glsl has the real ones).
vec4 transmittanceLutTexel(int b, int x, int y) { return vec4(b + x + y); }
vec4 multipleScatteringLutTexel(int b, int x, int y) { return vec4(b + x + y); }

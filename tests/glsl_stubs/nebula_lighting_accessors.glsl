// Stand-in for the accessor pixel_shading.glsl reads the nebula's optical depth through (the
// lighting pass defines it in common_nebula_lighting.glsl, the CPU twin in nebula_cpu_twin.h).
float nebulaOpticalDepthAt(vec2 uv) { return uv.x; }

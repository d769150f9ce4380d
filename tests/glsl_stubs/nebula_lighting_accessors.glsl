// Stand-ins for the accessors pixel_shading.glsl reads the nebula through (the lighting pass
// defines them in common_nebula_lighting.glsl, the CPU twin in nebula_cpu_twin.h).
float nebulaOpticalDepthAt(vec2 uv) { return uv.x; }
NebulaLightConstants frameNebula() { return NebulaLightConstants(vec4(0.0f, 0.0f, 0.0f, 1.0f), 1, 8, 0, 0); }
vec4 nebulaStarData(int i) { return vec4(float(i)); }
float nebulaStarDepthAt(int star, vec3 pCube) { return float(star) * pCube.x; }

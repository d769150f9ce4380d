// Stand-ins for the accessors shaders/shared/pixel_shading.glsl expects its includer to define,
// so that the compile test can validate the file alone (shaders/lighting.frag has the real ones).
GpuBatch frameBatch(int b) { return GpuBatch(vec4(b), vec4(0.0), vec4(0.0), vec4(0.0)); }
GpuLight frameLight(int l) {
  return GpuLight(vec3(l), 0, vec3(0.0), 0.0, 0.0, 0.0, -1, 0.0, 0.0, 0.0, 0.0, 0.0, mat4(1.0),
                  vec4[kMaxShadowCascades](vec4(0.0, 0.0, 1.0, 0.0), vec4(0.0), vec4(0.0), vec4(0.0)), 1, 0, 0, 0);
}
GpuMaterial frameMaterial(int id) { return GpuMaterial(vec3(id), 0.0, 0.0, 0, 0, 0, kNoEmission, kNoEmission, 0.0, 0); }
vec4 frameLightSpectrum(int l, int b) { return vec4(l + b); }
vec4 frameMaterialSpectrum(int s, int b, int j) { return vec4(s + b + j); }
float shadowDepthAt(int layer, int x, int y) { return float(layer + x + y); }
vec3 upsamplingCoefficients(vec3 rgb) { return rgb; }
vec3 emissionCoefficients(vec3 rgb) { return rgb; }
WaterConstants frameWater() { return WaterConstants(1.0, 2.0, 0.0, 0.0); }
vec4 frameWaterSpectrum(int b, int j) { return vec4(b + j); }
SkyConstants frameSky() { return SkyConstants(6360.0, 0, 0.0, 0.0); }
GpuAtmosphere frameAtmosphere(int b) {
  return GpuAtmosphere(vec4(b), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
}

// A nebula in the scene (techniques/nebula: a scene's "nebula" section) dims what the camera sees
// through it: the nebula's march accumulates, per pixel, the optical depth g (µm: C_T·τ, its
// model's units) from the camera to the scene's surface, or through the whole nebula where no
// surface is, and the lighting pass multiplies each wavelength's radiance by e^(−g/λ), the
// model's own attenuation (τ(λ) = τ·C_T/λ), exactly at the frame's wavelengths. What the nebula
// itself emits and scatters its pass adds after lighting.
//
// Its stars light the scene's surfaces as point lights of their own (a nebula has any number of
// them, beyond the frame's kMaxLights), each dimmed on its way by e^(−g_s/λ), g_s the optical
// depth from the star to the point: the field the march precomputes per voxel for every method
// (NebulaPrecomputed::starDepth), read at the point inside the cube, or, outside it, where the
// segment from the point to the star enters it (beyond the cube there is no dust); a segment that
// misses the cube is not dimmed. Stars cast no shadows of surfaces (as no point light does).
//
// The optical depth is an R32F texture of the frame's size (row 0 at the bottom) at texture unit
// kNebulaOpticalDepthUnit of the lighting pass; the includer defines its accessor
//   float nebulaOpticalDepthAt(vec2 uv);   (uv: the pixel's centre in [0, 1]²)
// and the stars' accessors over the section's block and the star depths' texture:
//   NebulaLightConstants frameNebula();  vec4 nebulaStarData(int i);
//   float nebulaStarDepthAt(int star, vec3 pCube);   (trilinear between voxel centres)
// Requires: prelude.glsl nebula_march.glsl

const int kNebulaOpticalDepthUnit = 11;
const int kNebulaStarDepthUnit = 12;      // the march's star depths (nebula_march.comp's uField)
const int kNebulaLightConstantsBinding = 3;
const int kNebulaStarLightsBinding = 12;

// The section's block (techniques/nebula/nebula_section.h, pack).
struct NebulaLightConstants {
  vec4 boxMinSize;  // xyz: the unit cube's corner in the world (m); w: its side (m)
  int starCount;    // the stars that light surfaces (0: none do), all of the model's or none
  int voxelsZ;      // the density's nz: one slab of the star depths' texture
  int pad0;
  int pad1;
};
// Star s's entries of the block's data, each a vec4: its position (world, m) at the first, then
// per batch b its radiant intensity I(λ) (W·sr⁻¹·nm⁻¹) at the batch's four wavelengths (RGB mode:
// its linear RGB at 683 lm/W, as the frame's lights carry theirs).
PRISM_INLINE int nebulaStarPositionIndex(int star, int batchCount) { return star * (batchCount + 1); }
PRISM_INLINE int nebulaStarSpectrumIndex(int star, int batch, int batchCount) {
  return star * (batchCount + 1) + 1 + batch;
}

// Where star light reaching pCube (the unit cube's coordinates) is dimmed as the star's depth
// field says: pCube itself inside the cube, else the point where the segment from pCube to the
// star enters the cube; false when the segment misses it (the light arrives undimmed).
PRISM_INLINE bool nebulaStarDepthPoint(IN(vec3) pCube, IN(vec3) starCube, OUT(vec3) at) {
  at = pCube;
  if (min(min(pCube.x, pCube.y), pCube.z) >= 0.0f && max(max(pCube.x, pCube.y), pCube.z) <= 1.0f) return true;
  vec3 d = starCube - pCube;
  float t0;
  float t1;
  if (!nebulaClipToCube(pCube, d, 1.0f, t0, t1)) return false;
  at = pCube + d * t0;
  return true;
}

// In RGB mode a batch's channels are R, G, B, not wavelengths: the dimming is taken at the
// wavelengths RGB renderers stand them for (spectral/sampling.h's kRgbStandInWavelengthsNm), the
// fourth channel unused.
const vec4 kNebulaRgbStandInNm = vec4(680.0f, 550.0f, 440.0f, 550.0f);

// e^(−g/λ) at a batch's four wavelengths (nm); 1 for g = 0.
PRISM_INLINE vec4 nebulaTransmittance4(float gUm, IN(vec4) lambdaNm) {
  if (gUm <= 0.0f) return vec4(1.0f);
  float g = gUm * 1000.0f;  // nm
  return vec4(exp(-g / lambdaNm.x), exp(-g / lambdaNm.y), exp(-g / lambdaNm.z), exp(-g / lambdaNm.w));
}

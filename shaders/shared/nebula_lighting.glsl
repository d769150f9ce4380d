// A nebula in the scene (techniques/nebula: a scene's "nebula" section) dims what the camera sees
// through it: the nebula's march accumulates, per pixel, the optical depth g (µm: C_T·τ, its
// model's units) from the camera to the scene's surface, or through the whole nebula where no
// surface is, and the lighting pass multiplies each wavelength's radiance by e^(−g/λ), the
// model's own attenuation (τ(λ) = τ·C_T/λ), exactly at the frame's wavelengths. What the nebula
// itself emits and scatters its pass adds after lighting.
//
// The optical depth is an R32F texture of the frame's size (row 0 at the bottom) at texture unit
// kNebulaOpticalDepthUnit of the lighting pass; the includer defines its accessor
//   float nebulaOpticalDepthAt(vec2 uv);   (uv: the pixel's centre in [0, 1]²)
// Requires: prelude.glsl

const int kNebulaOpticalDepthUnit = 11;

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

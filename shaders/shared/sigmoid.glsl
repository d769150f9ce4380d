// The sigmoid-polynomial reflectance model of Jakob & Hanika 2019, "A Low-Dimensional Function
// Space for Efficient Spectral Upsampling", Eq. 3–4: f(λ) = S(c0·λ² + c1·λ + c2) with
// S(x) = ½ + x / (2·√(1 + x²)). The coefficients act on λ in nanometres. S maps ℝ onto (0, 1),
// so every such spectrum is a valid reflectance. Beyond |x| = 1e9 (S within 3e-19 of its
// limit) S is taken to 0 or 1: past ~1.8e19 x·x overflows, which gave ½ (or the NaN of ∞/∞).
// Guarded: sources that a unity build merges into one translation unit may each include it.
#ifndef PRISM_SIGMOID_GLSL
#define PRISM_SIGMOID_GLSL

PRISM_INLINE float sigmoid(float x) {
  if (abs(x) > 1e9f) return x > 0.0f ? 1.0f : 0.0f;
  return 0.5f + x / (2.0f * sqrt(1.0f + x * x));
}

// Evaluated in Horner form, (c0·λ + c1)·λ + c2, as Jakob & Hanika's reference code does.
PRISM_INLINE float sigmoidSpectrum(IN(vec3) coeffs, float lambdaNm) {
  return sigmoid((coeffs.x * lambdaNm + coeffs.y) * lambdaNm + coeffs.z);
}

// One batch of four wavelengths, the unit every spectral pass works in.
PRISM_INLINE vec4 sigmoidSpectrum4(IN(vec3) coeffs, IN(vec4) lambdaNm) {
  return vec4(sigmoidSpectrum(coeffs, lambdaNm.x), sigmoidSpectrum(coeffs, lambdaNm.y),
              sigmoidSpectrum(coeffs, lambdaNm.z), sigmoidSpectrum(coeffs, lambdaNm.w));
}

// Prism's upsampled reflectance: the sigmoid polynomial on [380, 730] nm, held at its end values
// outside. CIE 1931's x̄+ȳ+z̄ is below 0.6 % of its peak beyond that band, so colour hardly
// constrains the polynomial there, and for saturated dark colours it climbs back towards 1 past
// ~730 nm (and below 380 nm): spurious infrared and ultraviolet reflectance that a camera, an
// incandescent lamp or an underwater path would see. The table optimiser fits this same
// clamped model, so the colours stay exact and the tails stay flat.
const float kReflectanceMinNm = 380.0f;
const float kReflectanceMaxNm = 730.0f;

PRISM_INLINE float upsampledReflectance(IN(vec3) coeffs, float lambdaNm) {
  return sigmoidSpectrum(coeffs, clamp(lambdaNm, kReflectanceMinNm, kReflectanceMaxNm));
}

PRISM_INLINE vec4 upsampledReflectance4(IN(vec3) coeffs, IN(vec4) lambdaNm) {
  return sigmoidSpectrum4(coeffs, clamp(lambdaNm, vec4(kReflectanceMinNm), vec4(kReflectanceMaxNm)));
}

// pbrt-v4's scale of an unbounded colour (emission, values above 1; spectral/rgb_intent.h's
// RgbUnboundedSpectrum): 2·max of its channels, so that the reflectance fitted to rgb / scale has
// its largest channel ½, clear of the unreachable pure white. Channels finite and ≥ 0.
PRISM_INLINE float unboundedScale(IN(vec3) rgb) { return 2.0f * max(max(rgb.x, rgb.y), rgb.z); }

// dS/dx = 1 / (2·(1 + x²)^(3/2)), for optimisers that fit the coefficients.
PRISM_INLINE float sigmoidDerivative(float x) {
  if (isinf(x)) return 0.0f;
  float s = 1.0f + x * x;
  return 0.5f / (s * sqrt(s));
}

#endif  // PRISM_SIGMOID_GLSL

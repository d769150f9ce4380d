// The constants every side shares, defined once: prelude.glsl includes this file for the GPU and
// shared_cpp.h for C++ (inside prism::shared). Double-precision C++ code converts them; both
// values are exact in a float's 24 bits where it matters (683 is). Guarded: every file that
// includes the prelude gets it, and the offline GLSL check includes it once more.
#ifndef PRISM_CONSTANTS_GLSL
#define PRISM_CONSTANTS_GLSL

const float kPi = 3.14159265358979f;

// The maximum luminous efficacy of radiation, lm/W: photometric quantities are kLumensPerWatt ·
// ∫ S(λ) ȳ(λ) dλ (CIE 1931 ȳ peaks at 555 nm; the SI's 683 lm/W is defined at 540 THz ≈
// 555.016 nm, and the difference, 683.002 at the ȳ peak, is below the tabulation's precision).
const float kLumensPerWatt = 683.0f;
#endif

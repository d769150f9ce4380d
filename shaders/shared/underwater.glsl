// Light under water in closed form: Monzón et al. 2024's analytic single-scattering ocean, as
// Pérez García 2024 (Eq. 3.17) couples it with spectral upsampling of the sea floor. Water is a
// homogeneous medium of scattering σs, extinction σt = σa + σs and diffuse attenuation of
// downwelling irradiance Kd (all per metre, per wavelength: a vec4 batch); sunlight reaches depth
// z as E(z) = E(0)·e^(−Kd·z) (Kd already accounts for the light that forward scattering keeps in
// the downwelling field, which is why the model uses it rather than σt for the sun's leg).
//
// Derivation, in this engine's conventions. Depth z grows downwards from the water surface. The
// camera is at depth z_c; a view ray leaves it along the unit direction d towards a surface point
// at distance S, and gains depth w = −d_y per metre (world y points up). The thesis writes the
// same with ω = −d, the direction from the surface to the camera, so Kd·ω_y − σt = −(Kd·w + σt).
// A point s metres along the ray lies at depth z_c + w·s and, scattering isotropically (phase
// 1/4π), sends towards the camera σs·E(z_c + w·s)/(4π) per metre, attenuated by e^(−σt·s) on the
// way back:
//   L_in = ∫₀^S σs/(4π) · E(0)·e^(−Kd·(z_c + w·s)) · e^(−σt·s) ds
//        = σs·E(0)·e^(−Kd·z_c)/(4π) · (1 − e^(−x·S)) / x,          x = Kd·w + σt,
// which is the thesis's σs·E(0)·e^(−Kd·O_y)/(4π(Kd·ω_y − σt))·[e^((Kd·ω_y − σt)·S) − 1]. The
// surface point itself is seen through T = e^(−σt·S) and lit by E(z_s)·(α/π)·cos θ: the
// rasteriser's own BRDF under the sunlight that reaches its depth. For |x·S| < 1e-3 the
// quotient (1 − e^(−xS))/x is its series S·(1 − xS/2 + (xS)²/6), which keeps it exact as x → 0
// (looking up where Kd > σt, as in clear water beyond 675 nm), where the closed form is 0/0.
// Elsewhere e^(−Kd·z_c)·(1 − e^(−xS)) is taken as e^(−Kd·z_c) − e^(−Kd·z_c − xS): looking up
// through strongly attenuating water (x < 0, Kd large), e^(−xS) alone overflows float while the
// product stays finite (the second exponent is the ray end's own attenuation, ≤ 0 where that end
// is under water, and held there against rounding).

// The water's block of the lighting pass (techniques/underwater/water_section.h packs it): its
// constants in a std140 uniform block, and per batch σs (j = 0), σt = σa + σs (j = 1) and Kd
// (j = 2), 1/m, and the scene's distant environment's part of E(0) (j = 3: its radiance over the
// sky's hemisphere, ∫ L dω, in the lights' units; 0 when the scene has no environment) in a
// storage buffer at waterSpectrumIndex(b, j).
const int kWaterConstantsBinding = 1;
const int kWaterSpectraBinding = 5;
struct WaterConstants {
  float surfaceY;        // world height of the water surface (m)
  float depthM;          // the camera's depth below it
  float lampScattering;  // 1: point and spot lamps scatter into the view (underwater_lamps.glsl); 0: not
  float pad0;
};
PRISM_INLINE int waterSpectrumIndex(int batch, int j) { return batch * 4 + j; }

// The single-scattered radiance reaching the camera over S metres of the ray, per unit of
// downwelling irradiance at the surface (multiply by E(0)).
PRISM_INLINE vec4 waterInScattering(IN(vec4) sigmaS, IN(vec4) sigmaT, IN(vec4) kd, float cameraDepthM,
                                    float descentPerM, float distanceM) {
  vec4 result;
  for (int j = 0; j < 4; ++j) {
    float x = kd[j] * descentPerM + sigmaT[j];
    float xs = x * distanceM;
    float atCamera = -kd[j] * cameraDepthM;  // the exponents of e^(−Kd·z_c) and of it times e^(−xS)
    // The second is −Kd·z_end − σt·S ≤ 0 for a ray end at or below the surface, as the caller
    // clips it; rounding in z_end = z_c + w·S, times a Kd of 1e7/m and more, made it positive
    // enough to overflow.
    float atEnd = min(atCamera - xs, 0.0f);
    float scattered = abs(xs) < 1e-3f ? exp(atCamera) * distanceM * (1.0f - xs * 0.5f + xs * xs * (1.0f / 6.0f))
                                      : (exp(atCamera) - exp(atEnd)) / x;
    result[j] = sigmaS[j] * (1.0f / (4.0f * kPi)) * scattered;
  }
  return result;
}

// Beer–Lambert transmittance over a distance, per wavelength.
PRISM_INLINE vec4 waterTransmittance(IN(vec4) sigmaT, float distanceM) {
  return exp(-sigmaT * distanceM);
}

// The share of the straight segment between heights y0 and y1 (world y, m) that lies below the
// water surface at surfaceY: a lamp above the water lights a point below it through the water
// only on the segment's lower part (refraction at the surface left out).
PRISM_INLINE float shareBelowSurface(float y0, float y1, float surfaceY) {
  float low = min(y0, y1);
  float high = max(y0, y1);
  if (high <= surfaceY) return 1.0f;
  if (low >= surfaceY) return 0.0f;
  return (surfaceY - low) / (high - low);
}

// The share of the surface's downwelling irradiance left at a depth (≥ 0), per wavelength.
PRISM_INLINE vec4 downwellingAttenuation(IN(vec4) kd, float depthM) {
  return exp(-kd * max(depthM, 0.0f));
}

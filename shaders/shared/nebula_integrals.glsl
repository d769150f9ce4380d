// Closed-form spectral integrals of the nebula model (Barrès 2023, "Real-time spectral rendering
// of nebulae", §4 and its appendix). Under the model's attenuation τ(λ) = τ·C_T/λ, light that
// crossed an optical depth g = τ·C_T (µm) is attenuated by e^(−g/λ); the sensor's response to it
// through a polynomial P(λ) = Σ cₙλⁿ (filter × star × scattering, λ in µm) is
//   ∫ P(λ)·e^(−x/λ) dλ = Σ cₙ [Iₙ(λ₁) − Iₙ(λ₀)],   Iₙ(λ) an antiderivative of λⁿ·e^(−x/λ).
// The paper's recurrence (integration by parts), Iₙ = βₙ + x/(n+1)·αₙ, β₀ = λe^(−x/λ),
// α₀ = −E₁(x/λ), is the exponential integrals' recurrence E_{m+1}(z) = (e^(−z) − z·E_m(z))/m run
// upwards from E₁ in disguise:
//   Iₙ(λ) = λⁿ⁺¹·E_{n+2}(x/λ)    (d/dλ: E_m' = −E_{m−1} and the recurrence give λⁿe^(−x/λ)).
// Run upwards it multiplies an error by z/m a step, which at z = x/λ ≫ m loses all of float's
// digits (0.11 relative at n = 7, x = 10 µm); run downwards (E_m = (e^(−z) − m·E_{m+1})/z) by m/z.
// So each z starts where neither grows: E_M by its continued fraction at M = ⌊z⌋ + 1 (up to 9),
// or E₂ from E₁'s series below z = 1, then upwards above M and downwards below it.
//
// The file is compiled three times: as GLSL, and as C++ in float (what the GPU runs) and in double
// (techniques/nebula/nebula_integrals.h), through NEBULA_REAL / NEBULA_VEC4.
#ifndef NEBULA_REAL
#define NEBULA_REAL float
#define NEBULA_VEC4 vec4
#endif
#ifndef NEBULA_CF_DEPTH
#define NEBULA_CF_DEPTH 24
#endif

// E_m(u) = ∫₁^∞ e^(−ut)/tᵐ dt for u ≥ 1 by its continued fraction (Abramowitz & Stegun 1964,
// 5.1.22, in the even form e^(−u)/(u+m− 1·m/(u+m+2− 2(m+1)/(u+m+4− …)))), evaluated bottom-up
// from depth NEBULA_CF_DEPTH (a multiple of 8), for m = 1…9 at u ≥ 1 (its slowest point is u = 1):
// 24 in float and GLSL, within 6e-8 relative, float's own rounding; 96 in double, within 3e-16
// (at 24 its 6e-8 became 3e-4 in the projection's coefficients, whose orthonormalisation cancels
// the raw moments by thousands).
//
// Its loop, and the series of nebulaE1 and nebulaInversePowerExpIntegrals, run in chunks of 8,
// loops of constant count that shader compilers unroll: Mesa's llvmpipe stops a shader's loops
// after 65 535 iterations an invocation, nested loops counted together, and the analytic march
// (these per sample, star, channel and passband piece) splits into fewer dispatches the fewer it
// counts (techniques/nebula/gpu/nebula_march_segments.h).
PRISM_INLINE NEBULA_REAL nebulaEnContinuedFraction(int m, NEBULA_REAL u) {
  NEBULA_REAL order = NEBULA_REAL(m);
  NEBULA_REAL f = 0.0f;
  for (int k0 = NEBULA_CF_DEPTH; k0 >= 1; k0 -= 8) {
    for (int j = 0; j < 8; ++j) {
      NEBULA_REAL kk = NEBULA_REAL(k0 - j);
      f = kk * (order + kk - 1.0f) / (u + order + 2.0f * kk - f);
    }
  }
  return exp(-u) / (u + order - f);
}

// E₁(u) = ∫₁^∞ e^(−ut)/t dt for u > 0. Below u = 1 its power series (A&S 5.1.11),
// −γ − ln u + Σ (−1)^(k+1) uᵏ/(k·k!), 16 terms (the 17th is < 1e-15); above, the continued
// fraction. Float stays within 5e-7 relative.
PRISM_INLINE NEBULA_REAL nebulaE1(NEBULA_REAL u) {
  if (u <= 1.0f) {
    NEBULA_REAL sum = 0.0f;
    NEBULA_REAL term = 1.0f;
    for (int k0 = 1; k0 <= 16; k0 += 8) {
      for (int j = 0; j < 8; ++j) {
        NEBULA_REAL k = NEBULA_REAL(k0 + j);
        term *= -u / k;
        sum -= term / k;
      }
    }
    return NEBULA_REAL(-0.57721566490153286) - log(u) + sum;
  }
  return nebulaEnContinuedFraction(1, u);
}

// E₂(u) for u ≥ 0: e^(−u) − u·E₁(u) below u = 1 (1 at u = 0, where u·E₁(u) → 0; the two terms
// cancel by at most 2.5×), the continued fraction above.
PRISM_INLINE NEBULA_REAL nebulaE2(NEBULA_REAL u) {
  if (u > 1.0f) return nebulaEnContinuedFraction(2, u);
  return u > 0.0f ? exp(-u) - u * nebulaE1(u) : NEBULA_REAL(1.0f);
}

// E₂(u)…E₉(u) for u ≥ 0 (E₂…E₅ in lo, E₆…E₉ in hi), each within a few roundings of its value:
// E_M directly (E₂ below u = 1, else the continued fraction at M = min(⌊u⌋ + 1, 9)), the orders above
// M upwards and those below it downwards, so that no step multiplies an error by more than 1.
PRISM_INLINE void nebulaExponentialIntegrals(NEBULA_REAL u, OUT(NEBULA_VEC4) lo, OUT(NEBULA_VEC4) hi) {
  NEBULA_REAL e = exp(-u);
  int start = u > 1.0f ? int(min(u, NEBULA_REAL(8.0f))) + 1 : 2;  // ⌊u⌋ + 1 ≥ u
  NEBULA_REAL values[8];  // E₂…E₉
  values[start - 2] = start == 2 ? nebulaE2(u) : nebulaEnContinuedFraction(start, u);
  for (int m = 2; m < 9; ++m) {
    if (m >= start) values[m - 1] = (e - u * values[m - 2]) / NEBULA_REAL(m);
  }
  for (int m = 8; m >= 2; --m) {
    if (m < start) values[m - 2] = (e - NEBULA_REAL(m) * values[m - 1]) / u;
  }
  for (int i = 0; i < 4; ++i) {
    lo[i] = values[i];
    hi[i] = values[i + 4];
  }
}

// e^(−x/λ), x ≥ 0, λ ≥ 0: 1 at x = 0 even where λ = 0 (the paper's domain starts there), where
// x/λ would be 0/0.
PRISM_INLINE NEBULA_REAL nebulaAttenuation(NEBULA_REAL x, NEBULA_REAL lambdaUm) {
  return x > 0.0f ? exp(-x / lambdaUm) : NEBULA_REAL(1.0f);
}

// I₀…I₇ at λ (µm) for optical depth x (µm): Iₙ(λ) = λⁿ⁺¹·E_{n+2}(x/λ), antiderivatives of
// λⁿ·e^(−x/λ), n = 0…3 in lo and 4…7 in hi; 0 at λ = 0 (their limit for x > 0; at x = 0 too).
PRISM_INLINE void nebulaPowerExpAntiderivatives(NEBULA_REAL x, NEBULA_REAL lambdaUm, OUT(NEBULA_VEC4) lo,
                                                OUT(NEBULA_VEC4) hi) {
  if (lambdaUm <= 0.0f) {
    lo = NEBULA_VEC4(0.0f);
    hi = NEBULA_VEC4(0.0f);
    return;
  }
  nebulaExponentialIntegrals(x / lambdaUm, lo, hi);
  NEBULA_REAL power = lambdaUm;  // λⁿ⁺¹
  for (int n = 0; n < 8; ++n) {
    if (n < 4) {
      lo[n] *= power;
    } else {
      hi[n - 4] *= power;
    }
    power *= lambdaUm;
  }
}

// ∫_λ₀^λ₁ λⁿ·e^(−x/λ) dλ for n = 0…7 (lo: 0…3, hi: 4…7).
PRISM_INLINE void nebulaPowerExpIntegrals(NEBULA_REAL x, NEBULA_REAL lambda0Um, NEBULA_REAL lambda1Um,
                                          OUT(NEBULA_VEC4) lo, OUT(NEBULA_VEC4) hi) {
  NEBULA_VEC4 lo0;
  NEBULA_VEC4 hi0;
  NEBULA_VEC4 lo1;
  NEBULA_VEC4 hi1;
  nebulaPowerExpAntiderivatives(x, lambda0Um, lo0, hi0);
  nebulaPowerExpAntiderivatives(x, lambda1Um, lo1, hi1);
  lo = lo1 - lo0;
  hi = hi1 - hi0;
}

// ∫_λ₀^λ₁ P(λ)·e^(−x/λ) dλ for P(λ) = Σₙ cₙλⁿ of degree ≤ 7 (coefficients c₀…c₃ in cLo, c₄…c₇
// in cHi, λ in µm): the analytic method's integral per ray step (Barrès 2023, Eq. 9).
PRISM_INLINE NEBULA_REAL nebulaPolyExpIntegral(IN(NEBULA_VEC4) cLo, IN(NEBULA_VEC4) cHi, NEBULA_REAL x,
                                               NEBULA_REAL lambda0Um, NEBULA_REAL lambda1Um) {
  NEBULA_VEC4 lo;
  NEBULA_VEC4 hi;
  nebulaPowerExpIntegrals(x, lambda0Um, lambda1Um, lo, hi);
  return dot(cLo, lo) + dot(cHi, hi);
}

// Negative powers (the paper's appendix), for a Wien star A·λ⁻⁵·e^(−B/λ) in closed form: with
// u = 1/λ and m = k − 2, ∫_λ₀^λ₁ λ^(−k)·e^(−x/λ) dλ = ∫_u₁^u₀ u^m·e^(−xu) du = G_m(u₀) − G_m(u₁),
// G_m(u) = ∫₀^u t^m e^(−xt) dt = (m!/x^(m+1))·P(m+1, xu), P the regularised lower incomplete gamma
// function. The difference of two G's keeps its digits only where G is small against m!/x^(m+1),
// so each m takes one of two forms, at both bounds alike, by z = xu at the interval's middle
// against P's median (≈ m + ⅔):
// - z < m + 0.7: the series G_m = u^(m+1)·e^(−z)·Σₙ zⁿ/((m+1)(m+2)…(m+1+n)), 40 terms of one sign
//   (z ≤ 6 at either bound on the visible band: the last below 1e-15 of the sum), exact at x = 0;
// - else by parts, G_m = m!/x^(m+1) − e^(−xu)·S_m, S₀ = 1/x, S_m = (u^m + m·S_{m−1})/x, the
//   constant dropping out of the difference (what is left is the small upper part, Q = 1 − P).
// Returned for k = 5, 4, 3, 2 (m = 3, 2, 1, 0), in that order.
PRISM_INLINE NEBULA_VEC4 nebulaInversePowerExpIntegrals(NEBULA_REAL x, NEBULA_REAL lambda0Um, NEBULA_REAL lambda1Um) {
  NEBULA_REAL u0 = 1.0f / lambda0Um;
  NEBULA_REAL u1 = 1.0f / lambda1Um;
  NEBULA_REAL z0 = x * u0;
  NEBULA_REAL z1 = x * u1;
  NEBULA_REAL zMiddle = 0.5f * (z0 + z1);
  NEBULA_REAL e0 = exp(-z0);
  NEBULA_REAL e1 = exp(-z1);
  NEBULA_REAL s0 = 0.0f;  // S_m at both bounds (x > 0 wherever it is used)
  NEBULA_REAL s1 = 0.0f;
  NEBULA_REAL p0 = 1.0f;  // u^m
  NEBULA_REAL p1 = 1.0f;
  NEBULA_VEC4 result;
  for (int m = 0; m < 4; ++m) {
    if (m > 0) {
      p0 *= u0;
      p1 *= u1;
    }
    if (zMiddle >= NEBULA_REAL(m) + 0.7f) {
      s0 = m == 0 ? 1.0f / x : (p0 + NEBULA_REAL(m) * s0) / x;
      s1 = m == 0 ? 1.0f / x : (p1 + NEBULA_REAL(m) * s1) / x;
      result[3 - m] = e1 * s1 - e0 * s0;
    } else {
      if (x > 0.0f) {  // kept for a later m that takes the other form
        s0 = m == 0 ? 1.0f / x : (p0 + NEBULA_REAL(m) * s0) / x;
        s1 = m == 0 ? 1.0f / x : (p1 + NEBULA_REAL(m) * s1) / x;
      }
      NEBULA_REAL t0 = 1.0f / NEBULA_REAL(m + 1);
      NEBULA_REAL t1 = t0;
      NEBULA_REAL sum0 = t0;
      NEBULA_REAL sum1 = t1;
      for (int n0 = 1; n0 < 40; n0 += 8) {  // in chunks of 8 (nebulaEnContinuedFraction says why)
        for (int j = 0; j < 8 && n0 + j < 40; ++j) {
          t0 *= z0 / NEBULA_REAL(m + 1 + n0 + j);
          t1 *= z1 / NEBULA_REAL(m + 1 + n0 + j);
          sum0 += t0;
          sum1 += t1;
        }
      }
      result[3 - m] = p0 * u0 * e0 * sum0 - p1 * u1 * e1 * sum1;
    }
  }
  return result;
}

// ∫_λ₀^λ₁ λ⁻⁵·Q(λ)·e^(−x/λ) dλ for a cubic Q(λ) = Σₙ cₙλⁿ (c₀…c₃ in c, λ in µm), x ≥ 0: a
// passband piece times a Wien star, whose e^(−B/λ) joins the attenuation's (x = g + B).
PRISM_INLINE NEBULA_REAL nebulaWienPolyIntegral(IN(NEBULA_VEC4) c, NEBULA_REAL x, NEBULA_REAL lambda0Um,
                                                NEBULA_REAL lambda1Um) {
  return dot(c, nebulaInversePowerExpIntegrals(x, lambda0Um, lambda1Um));
}

// The closed forms above lose their digits on a narrow piece: over [λ₀, λ₁] with centre c and
// half-width h, P's coefficients in powers of λ are about (c/h)^degree times its values, and
// Σ cₙIₙ cancels them (a 0.8 nm piece of a Hubble passband at 656 nm, P_S quadratic and P_L
// quintic: not a digit left, even in double). There the analytic method takes the same integral
// as a series in the optical depth. With λ = c + h·s, ε = h/c and G = 1/(1 − ε),
//   e^(−x/λ) = e^(−x/c)·e^(u·γ(s)),  u = x·h·G/c²,  γ(s) = s/((1 + ε·s)·G),  |γ| ≤ 1 for |s| ≤ 1,
// so ∫_λ₀^λ₁ P(λ)·e^(−x/λ) dλ = e^(−x/c)·Σ_d V_d·u^d with V_d = h/d!·∫₋₁¹ P(c + h·s)·γ(s)^d ds,
// made ahead in double from P's factors (nebula_analytic_pieces.h). Twelve terms: for u ≤ 1 what
// is left out is below Σ_{d≥12} 1/d! ≈ 2.3e-9 of ∫|P| dλ, and the sum's terms, each at most
// u^d/d!·∫|P| dλ, cancel by at most e^(2u) ≈ 7.4 where P ≥ 0. u ≤ 1 up to x = c²/(h·G): about
// 1 000 µm for that Hubble piece (far past float's range of e^(−x/λ)), 12 µm for the bluest 25 nm
// CIE piece; beyond, the closed form, where x/c > (1 − ε)/ε already dims the piece below
// e^(1 − 1/ε). (In double the V_d's own error is P's: a narrow quadratic filter piece evaluated in
// powers of λ is good to about (c/h)²·1e-16.)
const NEBULA_REAL kNebulaSeriesMaxU = 1.0f;

// One piece of the analytic method's P (filter × star fit × scattering; for a Wien star, filter
// × normalisation × scattering against λ⁻⁵ with x + B), in both forms: V₀…V₁₁ in series0…2;
// bounds = (λ₀, λ₁, 1/c, h·G/c²) in µm; P's c₀…c₃ in cLo and c₄…c₇ in cHi (a Wien star: its
// cubic Q of λ⁻⁵·Q in cLo) for the closed form.
struct NebulaAnalyticPiece {
  NEBULA_VEC4 series0;
  NEBULA_VEC4 series1;
  NEBULA_VEC4 series2;
  NEBULA_VEC4 bounds;
  NEBULA_VEC4 cLo;
  NEBULA_VEC4 cHi;
};

// ∫_λ₀^λ₁ P(λ)·e^(−x/λ) dλ over one piece, x ≥ 0 (for a Wien star, wien true and x already
// holding its B): the series where u ≤ 1, else the closed form.
PRISM_INLINE NEBULA_REAL nebulaAnalyticPieceIntegral(IN(NebulaAnalyticPiece) piece, NEBULA_REAL x, bool wien) {
  NEBULA_REAL u = x * piece.bounds.w;
  if (u <= kNebulaSeriesMaxU) {
    NEBULA_REAL sum = piece.series2[3];
    for (int d = 2; d >= 0; --d) sum = sum * u + piece.series2[d];
    for (int d = 3; d >= 0; --d) sum = sum * u + piece.series1[d];
    for (int d = 3; d >= 0; --d) sum = sum * u + piece.series0[d];
    return exp(-x * piece.bounds.z) * sum;
  }
  return wien ? nebulaWienPolyIntegral(piece.cLo, x, piece.bounds.x, piece.bounds.y)
              : nebulaPolyExpIntegral(piece.cLo, piece.cHi, x, piece.bounds.x, piece.bounds.y);
}

// ∫_λ₀^λ₁ e^(−x/λ) dλ = I₀(λ₁) − I₀(λ₀), I₀(λ) = λ·E₂(x/λ): the inner product of two
// exponentials e^(−a/λ) and e^(−b/λ) with x = a + b, which is all the projection on an exp(−a/λ)
// basis needs.
PRISM_INLINE NEBULA_REAL nebulaExpIntegral(NEBULA_REAL x, NEBULA_REAL lambda0Um, NEBULA_REAL lambda1Um) {
  NEBULA_REAL i1 = lambda1Um > 0.0f ? lambda1Um * nebulaE2(x / lambda1Um) : NEBULA_REAL(0.0f);
  NEBULA_REAL i0 = lambda0Um > 0.0f ? lambda0Um * nebulaE2(x / lambda0Um) : NEBULA_REAL(0.0f);
  return i1 - i0;
}

// The raw moments of an attenuation e^(−x/λ) on four basis exponentials e^(−aⱼ/λ):
// mⱼ = ∫ e^(−(x + aⱼ)/λ) dλ over [λ₀, λ₁]. The projection method accumulates these along the ray
// and turns them into the orthonormal basis's coefficients once per pixel (linearity).
PRISM_INLINE NEBULA_VEC4 nebulaExpMoments(NEBULA_REAL x, IN(NEBULA_VEC4) a, NEBULA_REAL lambda0Um,
                                          NEBULA_REAL lambda1Um) {
  NEBULA_VEC4 m;
  for (int j = 0; j < 4; ++j) m[j] = nebulaExpIntegral(x + a[j], lambda0Um, lambda1Um);
  return m;
}

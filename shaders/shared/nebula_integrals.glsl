// Closed-form spectral integrals of the nebula model (Barrès 2023, "Real-time spectral rendering
// of nebulae", §4 and its appendix). Under the model's attenuation τ(λ) = τ·C_T/λ, light that
// crossed an optical depth g = τ·C_T (µm) is attenuated by e^(−g/λ); the sensor's response to it
// through a polynomial P(λ) = Σ cₙλⁿ (filter × star × scattering, λ in µm) is
//   ∫ P(λ)·e^(−x/λ) dλ = Σ cₙ [Iₙ(λ₁) − Iₙ(λ₀)],   Iₙ(λ) an antiderivative of λⁿ·e^(−x/λ),
// with (integration by parts; the paper's recurrence, written here with γₙ = x·αₙ so that x = 0,
// where E₁(0) = ∞ but x·E₁(x/λ) → 0, needs no special case beyond xE₁):
//   Iₙ = βₙ + γₙ/(n+1),  β₀ = λ·e^(−x/λ),  βₙ = λ·n/(n+1)·βₙ₋₁  (= λⁿ⁺¹e^(−x/λ)/(n+1)),
//   γ₀ = −x·E₁(x/λ),     γₙ = −x·βₙ₋₁ − (x/n)·γₙ₋₁.
// E₁ is evaluated once per bound. The recurrence runs forward: each step multiplies an error by
// x/((n+1)λ), so in float its relative error grows with x/λ and n (tests/README give the figures).
//
// The file is compiled three times: as GLSL, and as C++ in float (what the GPU runs) and in double
// (techniques/nebula/nebula_integrals.h), through NEBULA_REAL / NEBULA_VEC4.
#ifndef NEBULA_REAL
#define NEBULA_REAL float
#define NEBULA_VEC4 vec4
#endif

// E₁(u) = ∫₁^∞ e^(−ut)/t dt for u > 0 (Abramowitz & Stegun 1964, 5.1.11 and 5.1.22). Below u = 1
// its power series, −γ − ln u + Σ (−1)^(k+1) uᵏ/(k·k!), 16 terms (the 17th is < 1e-15); above,
// the continued fraction e^(−u)/(u+1− 1²/(u+3− 2²/(u+5− …))) evaluated bottom-up from depth 24,
// which at u = 1 (its slowest point) is within 5e-8 relative; float stays within 5e-7.
//
// Its loops, and the series of nebulaInversePowerExpIntegrals, run in chunks of 8, loops of
// constant count that shader compilers unroll: Mesa's llvmpipe stops a shader's loops after 65 535
// iterations an invocation, nested loops counted together (nebula_march.comp), which the analytic
// method's march (these per sample, star, channel and passband piece) would pass.
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
  NEBULA_REAL f = 0.0f;
  for (int k0 = 24; k0 >= 1; k0 -= 8) {
    for (int j = 0; j < 8; ++j) {
      NEBULA_REAL kk = NEBULA_REAL(k0 - j);
      f = kk * kk / (u + 2.0f * kk + 1.0f - f);
    }
  }
  return exp(-u) / (u + 1.0f - f);
}

// e^(−x/λ), x ≥ 0, λ ≥ 0: 1 at x = 0 even where λ = 0 (the paper's domain starts there), where
// x/λ would be 0/0.
PRISM_INLINE NEBULA_REAL nebulaAttenuation(NEBULA_REAL x, NEBULA_REAL lambdaUm) {
  return x > 0.0f ? exp(-x / lambdaUm) : NEBULA_REAL(1.0f);
}

// x·E₁(x/λ), x ≥ 0, λ ≥ 0: 0 at x = 0 (its limit) and at λ = 0.
PRISM_INLINE NEBULA_REAL nebulaXE1(NEBULA_REAL x, NEBULA_REAL lambdaUm) {
  return x > 0.0f && lambdaUm > 0.0f ? x * nebulaE1(x / lambdaUm) : NEBULA_REAL(0.0f);
}

// I₀…I₇ at λ (µm) for optical depth x (µm): antiderivatives of λⁿ·e^(−x/λ), n = 0…3 in lo and
// 4…7 in hi.
PRISM_INLINE void nebulaPowerExpAntiderivatives(NEBULA_REAL x, NEBULA_REAL lambdaUm, OUT(NEBULA_VEC4) lo,
                                                OUT(NEBULA_VEC4) hi) {
  NEBULA_REAL beta = lambdaUm * nebulaAttenuation(x, lambdaUm);
  NEBULA_REAL gamma = -nebulaXE1(x, lambdaUm);
  lo[0] = beta + gamma;
  for (int n = 1; n < 8; ++n) {
    NEBULA_REAL fn = NEBULA_REAL(n);
    gamma = -x * beta - (x / fn) * gamma;
    beta = lambdaUm * fn / (fn + 1.0f) * beta;
    NEBULA_REAL value = beta + gamma / (fn + 1.0f);
    if (n < 4) {
      lo[n] = value;
    } else {
      hi[n - 4] = value;
    }
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
      for (int n0 = 1; n0 < 40; n0 += 8) {  // in chunks of 8 (nebulaE1 says why)
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

// ∫_λ₀^λ₁ e^(−x/λ) dλ = I₀(λ₁) − I₀(λ₀): the inner product of two exponentials e^(−a/λ) and
// e^(−b/λ) with x = a + b, which is all the projection on an exp(−a/λ) basis needs.
PRISM_INLINE NEBULA_REAL nebulaExpIntegral(NEBULA_REAL x, NEBULA_REAL lambda0Um, NEBULA_REAL lambda1Um) {
  NEBULA_REAL i1 = lambda1Um * nebulaAttenuation(x, lambda1Um) - nebulaXE1(x, lambda1Um);
  NEBULA_REAL i0 = lambda0Um * nebulaAttenuation(x, lambda0Um) - nebulaXE1(x, lambda0Um);
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

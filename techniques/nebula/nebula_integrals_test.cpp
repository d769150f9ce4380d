// E₁…E₉, the power–exponential antiderivatives, the negative powers and the analytic method's
// integral per passband piece (shaders/shared/nebula_integrals.glsl) against adaptive Simpson quadrature in long double,
// independent of them (it shares no formula with them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "core/worst_of.h"
#include "techniques/nebula/nebula_analytic_pieces.h"
#include "techniques/nebula/nebula_integrals.h"

namespace {

using LD = long double;

LD simpson(const std::function<LD(LD)>& f, LD a, LD b, LD fa, LD fm, LD fb, LD whole, LD tol, int depth) {
  LD m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  LD flm = f(lm), frm = f(rm);
  LD left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::fabs(left + right - whole) <= 15 * tol) return left + right + (left + right - whole) / 15;
  return simpson(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) + simpson(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}
// ∫_a^b f to an absolute tolerance `tol`, adaptive Simpson (Lyness 1969) in long double.
LD integrate(const std::function<LD(LD)>& f, LD a, LD b, LD tol) {
  LD fa = f(a), fb = f(b), fm = f((a + b) / 2);
  return simpson(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tol, 50);
}

// E₁(u) = ∫₀¹ e^(−u/s)/s ds (t = 1/s in its definition), split at s = u where the integrand peaks.
LD e1Reference(LD u) {
  auto f = [u](LD s) { return s <= 0 ? LD(0) : std::exp(-u / s) / s; };
  LD tol = 1e-14L;
  LD e = std::exp(-u);
  if (u < 1) return integrate(f, 0, u, tol * e) + integrate(f, u, 1, tol * e);
  return integrate(f, 0, 1, tol * e / u);
}

double relativeError(double value, LD reference) {
  return static_cast<double>(std::fabs((static_cast<LD>(value) - reference) / reference));
}

// The range used: attenuation exponents u = x/λ from 1e-6 (thin gas) to 80 (where e^(−u) leaves
// float's range), log-spaced.
TEST(NebulaIntegrals, E1MatchesQuadratureToOnePartInAMillion) {
  double worstDouble = 0, worstFloat = 0;
  for (int i = 0; i <= 200; ++i) {
    double u = std::pow(10.0, -6.0 + 7.9 * i / 200.0);
    float uf = static_cast<float>(u);
    worstDouble = prism::worstOf(worstDouble, relativeError(prism::shared::f64::nebulaE1(u), e1Reference(u)));
    worstFloat = prism::worstOf(worstFloat, relativeError(prism::shared::nebulaE1(uf), e1Reference(uf)));
  }
  std::printf("E1 max relative error: double %.3g, float %.3g\n", worstDouble, worstFloat);
  // The issue asks 1e-6; double holds 1e-12, which the projection's coefficients need (its
  // orthonormalisation cancels the raw moments by thousands).
  EXPECT_LE(worstDouble, 1e-12);
  // The float twin, evaluated at the float input (its rounding is the input's, not E₁'s).
  EXPECT_LE(worstFloat, 1e-6);
}

// E₂…E₉, each from its own continued fraction or series, or by the recurrence up or down from one
// that is (nebulaExponentialIntegrals), over the same range and at the orders' switch points:
// E_m(u) = ∫₀¹ s^(m−2)·e^(−u/s) ds (t = 1/s), E_m(0) = 1/(m − 1).
TEST(NebulaIntegrals, ExponentialIntegralsOfHigherOrderMatchQuadrature) {
  std::vector<double> us = {0.0, 1.0, 1.5, 2.0, 7.999, 8.0, 8.001, 9.0};
  for (int i = 0; i <= 50; ++i) us.push_back(std::pow(10.0, -6.0 + 7.9 * i / 50.0));
  double worstDouble = 0, worstFloat = 0;
  for (double u : us) {
    glm::dvec4 lo, hi;
    prism::shared::f64::nebulaExponentialIntegrals(u, lo, hi);
    glm::vec4 flo, fhi;
    const float uf = static_cast<float>(u);
    prism::shared::nebulaExponentialIntegrals(uf, flo, fhi);
    for (int m = 2; m <= 9; ++m) {
      auto reference = [m](LD v) {
        if (v == 0) return LD(1) / (m - 1);
        auto f = [m, v](LD s) { return s <= 0 ? LD(0) : std::pow(s, m - 2) * std::exp(-v / s); };
        return integrate(f, 0, 1, 1e-15L * std::exp(-v) / (1 + v));
      };
      const int i = m - 2;
      worstDouble = prism::worstOf(worstDouble, relativeError(i < 4 ? lo[i] : hi[i - 4], reference(u)));
      worstFloat = prism::worstOf(worstFloat, relativeError(i < 4 ? flo[i] : fhi[i - 4], reference(uf)));
    }
  }
  std::printf("E_2..E_9 max relative error: double %.3g, float %.3g\n", worstDouble, worstFloat);
  EXPECT_LE(worstDouble, 1e-12);
  EXPECT_LE(worstFloat, 1e-6);
  EXPECT_TRUE(std::isfinite(prism::shared::nebulaPolyExpIntegral(glm::vec4(1.0f), glm::vec4(1.0f), 0.0f, 0.38f, 0.78f)));
}

struct Worst {
  double error = 0;
  int n = 0;
  double x = 0, l0 = 0, l1 = 0;
  void update(double e, int n_, double x_, double l0_, double l1_) {
    if (e > error) *this = {e, n_, x_, l0_, l1_};
  }
};

// ∫_λ₀^λ₁ λⁿ e^(−x/λ) dλ, n = 0…7, over the intervals a render integrates (the visible band and
// sub-bands of it) and the paper's [0, 1] µm, x from 0 to 10 µm (optical depth τ ≈ 18).
TEST(NebulaIntegrals, PowerExponentialIntegralsMatchQuadrature) {
  const double intervals[][2] = {{0.38, 0.78}, {0.38, 0.48}, {0.6, 0.7}, {0.65, 0.66}, {0.001, 1.0}, {0.25, 1.0}};
  const double xs[] = {0.0, 1e-4, 0.01, 0.1, 0.3, 0.56, 1.0, 2.0, 4.0, 10.0};
  Worst worstDouble, worstFloat, worstFloatPerCancellation;
  for (const auto& iv : intervals) {
    for (double x : xs) {
      glm::dvec4 lo, hi;
      prism::shared::f64::nebulaPowerExpIntegrals(x, iv[0], iv[1], lo, hi);
      glm::vec4 flo, fhi;
      prism::shared::nebulaPowerExpIntegrals(static_cast<float>(x), static_cast<float>(iv[0]),
                                             static_cast<float>(iv[1]), flo, fhi);
      for (int n = 0; n < 8; ++n) {
        auto f = [n, x](LD l) { return std::pow(l, n) * std::exp(-static_cast<LD>(x) / l); };
        LD scale = std::pow(static_cast<LD>(iv[1]), n) * std::exp(-x / iv[1]) * (iv[1] - iv[0]);
        LD reference = integrate(f, iv[0], iv[1], scale * 1e-15L);
        double d = n < 4 ? lo[n] : hi[n - 4];
        double fl = n < 4 ? flo[n] : fhi[n - 4];
        worstDouble.update(relativeError(d, reference), n, x, iv[0], iv[1]);
        worstFloat.update(relativeError(fl, reference), n, x, iv[0], iv[1]);
        const double condition = iv[1] / (iv[1] - iv[0]) * (1.0 + x / iv[1]);
        worstFloatPerCancellation.update(relativeError(fl, reference) / condition, n, x, iv[0], iv[1]);
      }
    }
  }
  std::printf("I_n max relative error: double %.3g (n=%d x=%g [%g,%g]), float %.3g (n=%d x=%g [%g,%g]); float "
              "over its condition: %.3g (n=%d x=%g [%g,%g])\n",
              worstDouble.error, worstDouble.n, worstDouble.x, worstDouble.l0, worstDouble.l1, worstFloat.error,
              worstFloat.n, worstFloat.x, worstFloat.l0, worstFloat.l1, worstFloatPerCancellation.error,
              worstFloatPerCancellation.n, worstFloatPerCancellation.x, worstFloatPerCancellation.l0,
              worstFloatPerCancellation.l1);
  EXPECT_LE(worstDouble.error, 1e-6);  // the bound
  // Double loses what float does below, its condition λ₁/(λ₁ − λ₀)·(1 + x/λ₁) (at most 66·81 here),
  // in double's roundings: within 1e-10, where the 1e-6 lets through a continued fraction
  // cut short (6e-8 at depth 24).
  EXPECT_LE(worstDouble.error, 1e-10);
  // Float, as the GPU runs it: each antiderivative within a few roundings (E_m's, λⁿ⁺¹'s) of its
  // exponent x/λ, which e^(−x/λ) turns into a relative error x/λ times larger, and the definite
  // integral loses λ₁/(λ₁ − λ₀) to the bounds' cancellation (66 on 10 nm). With that condition,
  // λ₁/(λ₁ − λ₀)·(1 + x/λ₁), divided out: 8 roundings of 2⁻²⁴. (The recurrence run upwards from
  // E₁, the paper's, lost x/((n+1)λ) a step: 0.11 at n = 7, x = 10 µm on [0.38, 0.48].)
  EXPECT_LE(worstFloatPerCancellation.error, 8.0 * 0x1p-24);
}

// ∫_λ₀^λ₁ λ^(−k) e^(−x/λ) dλ, k = 2…5 (a Wien star λ⁻⁵e^(−B/λ) times a passband piece up to a
// cubic), over the visible band and sub-bands down to 10 nm, x from 0 (a star's B is ≥ 0.29 µm
// up to 50 000 K) to 10 µm, across both evaluations (the series to x/λ₀ = 8, then by parts).
TEST(NebulaIntegrals, NegativePowersMatchQuadrature) {
  const double intervals[][2] = {{0.38, 0.78}, {0.38, 0.48}, {0.6, 0.7}, {0.5, 0.525}, {0.65, 0.66}};
  const double xs[] = {0.0, 0.1, 0.3, 0.5, 1.0, 2.5, 3.2, 5.0, 10.0};
  Worst worstDouble, worstFloat;
  for (const auto& iv : intervals) {
    for (double x : xs) {
      const glm::dvec4 integrals = prism::shared::f64::nebulaInversePowerExpIntegrals(x, iv[0], iv[1]);
      for (int j = 0; j < 4; ++j) {
        const int k = 5 - j;
        auto f = [k, x](LD l) { return std::pow(l, -k) * std::exp(-static_cast<LD>(x) / l); };
        LD scale = std::pow(static_cast<LD>(iv[0]), -k) * std::exp(-x / iv[1]) * (iv[1] - iv[0]);
        LD reference = integrate(f, iv[0], iv[1], scale * 1e-15L);
        // c selects λ^(5−k) of Q, so that λ⁻⁵·Q = λ^(−k).
        glm::dvec4 c(0.0);
        c[5 - k] = 1.0;
        glm::vec4 cf(0.0f);
        cf[5 - k] = 1.0f;
        worstDouble.update(relativeError(integrals[j], reference), k, x, iv[0], iv[1]);
        EXPECT_NEAR(prism::shared::f64::nebulaWienPolyIntegral(c, x, iv[0], iv[1]), integrals[j],
                    1e-12 * std::fabs(integrals[j]));
        const double fe = relativeError(
            prism::shared::nebulaWienPolyIntegral(cf, static_cast<float>(x), static_cast<float>(iv[0]), static_cast<float>(iv[1])),
            reference);
        worstFloat.update(fe, k, x, iv[0], iv[1]);
      }
    }
  }
  std::printf("negative powers max relative error: double %.3g (k=%d x=%g [%g,%g]), float %.3g (k=%d x=%g [%g,%g])\n",
              worstDouble.error, worstDouble.n, worstDouble.x, worstDouble.l0, worstDouble.l1, worstFloat.error,
              worstFloat.n, worstFloat.x, worstFloat.l0, worstFloat.l1);
  EXPECT_LE(worstDouble.error, 1e-10);  // as the positive powers'
  // Float loses about λ/(λ₁ − λ₀) to the bounds' cancellation, and no more (the positive powers'
  // float bound, here over every interval).
  EXPECT_LE(worstFloat.error, 1e-4);
}

// The analytic method's integral per piece, ∫ P_S·P_L·e^(−x/λ) dλ (a Wien star: P_S·N·P_σ·λ⁻⁵
// with x + B), over every piece of the Hubble and CIE filters times a Planck star's fit and a
// Wien star, x from 0 to 30 µm: the series where u ≤ 1, the closed form beyond. Error relative to
// ∫|P|·e^(−x/λ) dλ (a fitted passband dips below 0 at its edges, where the integral can vanish).
TEST(NebulaIntegrals, AnalyticPiecesMatchQuadrature) {
  using prism::nebula::PolynomialPiece;
  const double xs[] = {0.0, 1e-3, 0.1, 1.0, 3.0, 10.0, 30.0};
  Worst seriesDouble, seriesFloat, closedDouble, closedFloat, closedFormOnNarrow, closedFormOnNarrowFloat;
  for (const char* filters : {"hubble", "cie1931"})
    for (auto model : {prism::nebula::StarModel::Planck, prism::nebula::StarModel::Wien}) {
      const auto star = prism::nebula::makeStarSpectrum(6000.0, model);
      const bool wien = model == prism::nebula::StarModel::Wien;
      const double b = wien ? prism::nebula::wienExponentUm(star.temperatureK) : 0.0;
      PolynomialPiece wienFactor = star.scattering;
      for (double& c : wienFactor.coeffs) c *= star.normalisation;
      const auto factors = wien ? std::vector<PolynomialPiece>{wienFactor} : star.fit.pieces;
      for (const auto& channel : prism::nebula::filterSet(filters).channels)
        for (const auto& filter : channel.response.pieces)
          for (const auto& factor : factors) {
            const double l0 = std::max(filter.lambda0Um, factor.lambda0Um), l1 = std::min(filter.lambda1Um, factor.lambda1Um);
            if (l1 <= l0) continue;
            const auto piece = prism::nebula::analyticPiece(filter, factor, l0, l1, wien);
            const auto pieceFloat = prism::nebula::toFloat(piece);
            for (double x0 : xs) {
              const double x = x0 + b;
              // In long double: P's powers of λ in double lose ~1e-10 to their cancellation, noise
              // that adaptive Simpson would chase.
              auto polynomial = [](const PolynomialPiece& q, LD l) {
                LD v = 0;
                for (int n = prism::nebula::kMaxDegree; n >= 0; --n) v = v * l + static_cast<LD>(q.coeffs[static_cast<std::size_t>(n)]);
                return v;
              };
              auto p = [&](LD l) {
                LD v = polynomial(filter, l) * polynomial(factor, l);
                return wien ? v / std::pow(l, 5) : v;
              };
              auto absolute = [&](LD l) { return std::fabs(p(l)) * std::exp(-static_cast<LD>(x) / l); };
              LD rough = 0;  // the largest of 65 samples times the width, for the tolerances
              for (int i = 0; i <= 64; ++i) rough = std::max(rough, absolute(l0 + (l1 - l0) * i / 64.0L));
              rough *= l1 - l0;
              if (rough == 0) continue;
              const LD scale = integrate(absolute, l0, l1, rough * 1e-10L);
              const LD reference = integrate([&](LD l) { return p(l) * std::exp(-static_cast<LD>(x) / l); }, l0, l1, rough * 1e-12L);
              auto error = [&](double value) { return static_cast<double>(std::fabs(static_cast<LD>(value) - reference) / scale); };
              const double d = error(prism::shared::f64::nebulaAnalyticPieceIntegral(piece, x, wien));
              const double f = error(prism::shared::nebulaAnalyticPieceIntegral(pieceFloat, static_cast<float>(x), wien));
              if (x * piece.bounds.w <= prism::shared::f64::kNebulaSeriesMaxU) {
                seriesDouble.update(d, 0, x, l0, l1);
                seriesFloat.update(f / (1.0 + x / l0), 0, x, l0, l1);
                if (l1 - l0 < 0.002)  // what the paper's closed form makes of a narrow piece
                  closedFormOnNarrow.update(error(wien ? prism::shared::f64::nebulaWienPolyIntegral(piece.cLo, x, l0, l1)
                                                       : prism::shared::f64::nebulaPolyExpIntegral(piece.cLo, piece.cHi, x, l0, l1)),
                                            0, x, l0, l1);
                if (l1 - l0 < 0.002) {
                  const auto xf = static_cast<float>(x);
                  const auto lf0 = static_cast<float>(l0), lf1 = static_cast<float>(l1);
                  closedFormOnNarrowFloat.update(
                      error(wien ? prism::shared::nebulaWienPolyIntegral(pieceFloat.cLo, xf, lf0, lf1)
                                 : prism::shared::nebulaPolyExpIntegral(pieceFloat.cLo, pieceFloat.cHi, xf, lf0, lf1)),
                      0, x, l0, l1);
                }
              } else {
                closedDouble.update(d, 0, x, l0, l1);
                closedFloat.update(f / (1.0 + x / l0), 0, x, l0, l1);
              }
            }
          }
    }
  auto show = [](const char* what, const Worst& w) {
    std::printf("%s: %.3g (x=%g [%g,%g])\n", what, w.error, w.x, w.l0, w.l1);
  };
  show("analytic pieces, series, double", seriesDouble);
  show("analytic pieces, series, float over its condition 1 + x/λ₀", seriesFloat);
  show("analytic pieces, closed form where u > 1, double", closedDouble);
  show("analytic pieces, closed form where u > 1, float over its condition", closedFloat);
  show("the closed form on the narrow pieces (not used there), double", closedFormOnNarrow);
  show("the closed form on the narrow pieces (not used there), float", closedFormOnNarrowFloat);
  // The series leaves out ≤ 2.3e-9 of e^(−x/c)·∫|P|, which is at most e times ∫|P|·e^(−x/λ).
  EXPECT_LE(seriesDouble.error, 1e-8);
  // Float: as the closed forms, a few roundings of the exponent x/λ, which e^(−x/λ) makes x/λ
  // times larger (x in float is already that far off), divided out as in the positive powers' bound.
  EXPECT_LE(seriesFloat.error, 8.0 * 0x1p-24);
  EXPECT_LE(closedDouble.error, 1e-8);  // as the series
  EXPECT_GT(closedDouble.x, 0.0);  // both forms were taken
  // And the series is needed where it is taken: there the closed form cancels beyond the GPU's
  // float altogether, and beyond the series' own bound in double.
  EXPECT_GT(closedFormOnNarrowFloat.error, 1.0);
  EXPECT_GT(closedFormOnNarrow.error, 100 * 1e-8);
}

}  // namespace


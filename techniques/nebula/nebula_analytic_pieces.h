// The analytic method's passband pieces (nebula_integrals.glsl's NebulaAnalyticPiece), made from
// the filters and the stars' spectra: per star and channel, P = P_S × P_L (the star's fit) or,
// for a Wien star while the product stays cubic, P_S × N·P_σ against its exact λ⁻⁵·e^(−B/λ).
// Each piece in both of the shared integral's forms: P's powers of λ for the paper's closed
// form, and the series' V₀…V₁₁ for the narrow pieces where that form has no digits left. In float
// (the GPU's and the CPU's float march) and in double.
#pragma once

#include <array>
#include <vector>

#include "techniques/nebula/nebula_integrals.h"
#include "techniques/nebula/nebula_spectra.h"

namespace prism::nebula {

struct AnalyticPieces {
  std::vector<std::array<std::vector<shared::NebulaAnalyticPiece>, 3>> f32;  // [star][channel]
  std::vector<std::array<std::vector<shared::f64::NebulaAnalyticPiece>, 3>> f64;
  // Per star, its B (µm) when its pieces are a Wien star's (x + B in the integrals), else 0.
  std::vector<double> wienExponentUm;
};

AnalyticPieces makeAnalyticPieces(const FilterSet& filters, const std::vector<StarSpectrum>& spectra);

// The piece of filter × factor over [λ₀, λ₁] (inside both), against λ⁻⁵ when `inversePower5`:
// the product's powers of λ and V_d = h/d!·∫₋₁¹ P(c + h·s)·γ(s)^d ds by 24-point Gauss–Legendre,
// each factor evaluated apart (their product's powers of λ would lose the digits the series keeps).
shared::f64::NebulaAnalyticPiece analyticPiece(const PolynomialPiece& filter, const PolynomialPiece& factor,
                                               double lambda0Um, double lambda1Um, bool inversePower5);
shared::NebulaAnalyticPiece toFloat(const shared::f64::NebulaAnalyticPiece& piece);

}  // namespace prism::nebula

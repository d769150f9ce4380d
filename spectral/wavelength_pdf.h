// A probability density over the wavelengths of [minNm, maxNm], tabulated per 1 nm bin (piecewise
// constant; the last bin may be shorter) and sampled by inverting its CDF: the pdfs that the
// Importance and Lights strategies of spectral/sampling.h draw from.
//
// Importance follows the observer alone: p(λ) ∝ r(λ), r = x̄ + ȳ + z̄ (or a camera's r̄ + ḡ + b̄),
// floored at 1e-3 of its mean so that no wavelength has pdf 0.
//
// Lights follows what a frame can actually see: the scene's emission E(λ) (its lights and
// background, scene/scene_emission.h) times each of the observer's curves c̄ (x̄ ȳ z̄, or a
// camera's), each curve given an equal share, mixed with the first:
//   p(λ) = (1 − α)·⅓·Σ_c E(λ)·c̄_c(λ) / ∫E·c̄_c dλ + α·p_Importance(λ),   α = kLightsDefensiveFraction.
// Equal shares, not E·(x̄ + ȳ + z̄): CIELAB works on each channel's ratio to white, so a channel
// the lamp barely excites needs the same relative accuracy as the brightest. Under a 450 nm LED
// ∫E·ȳ is 1/30 of ∫E·z̄, and E·(x̄ + ȳ + z̄) left Y, the lightness, to the few samples at the
// band's long-wave edge. Each share alone is the zero-variance pdf of its channel for a white
// surface; their equal mixture is the balance heuristic over the three (Veach 1997, thesis,
// ch. 9). Measured on one 16-wavelength frame of the ColorChecker (spectral/sampling_test.cpp,
// OneFrameOfTheColourChecker: mean ΔE00 over 32 frames), E·(x̄ + ȳ + z̄) → equal shares: the
// thesis's LED lamp 3.92 → 1.23, the blue LED 1.58 → 0.77, D65 2.10 → 1.92, A 1.37 → 1.43,
// F2 1.95 → 2.04, F11 1.52 → 1.87.
// The mixture is defensive importance sampling (Hesterberg 1995, Technometrics 37(2); Veach &
// Guibas 1995, SIGGRAPH, "Optimally combining sampling techniques"): E is only a proxy for the
// light that reaches the camera (lights are weighed by intensity alone, without their distance,
// and a technique's own scattered light, like the sky's, is not in it), so a wavelength the proxy
// misses must keep a pdf of at least α·p_Importance, which bounds its weight 1/(n·p) at 1/α = 10×
// Importance's. At 10 % the lamps still get 90 % of the samples (of 16 wavelengths, 13 or 14 fall
// within ±20 nm of a 20 nm LED's peak, where Importance puts 3 or 4), while a wavelength the
// proxy got wrong keeps a bounded weight instead of an unbounded one. When E·c̄ integrates to 0
// for every curve (a scene with no lights the observer sees) p is Importance's.
#pragma once

#include <vector>

#include "spectral/observer.h"
#include "spectral/spectrum.h"

namespace prism {

inline constexpr double kLightsDefensiveFraction = 0.1;

class WavelengthPdf {
 public:
  // Importance's pdf over [minNm, maxNm] (which must lie within 360–830 nm, min < max).
  static WavelengthPdf observerResponse(const Observer& obs, double minNm, double maxNm);
  // Lights' pdf: `emission` (negative values read as 0) × each of the observer's curves in equal
  // shares, mixed with observerResponse as above.
  static WavelengthPdf lightsAndObserver(const Spectrum& emission, const Observer& obs, double minNm,
                                         double maxNm);

  double minNm() const { return mEdgesNm.front(); }
  double maxNm() const { return mEdgesNm.back(); }
  // Per nm; 0 outside [minNm, maxNm].
  double density(double lambdaNm) const;
  // The wavelength whose CDF is u ∈ [0, 1], and the pdf there.
  struct Sample {
    double lambdaNm;
    double pdf;
  };
  Sample invert(double u) const;

 private:
  // weight per bin (per nm), any positive scale: normalised here.
  WavelengthPdf(std::vector<double> edgesNm, std::vector<double> weight);
  static std::vector<double> binEdges(double minNm, double maxNm);

  std::vector<double> mEdgesNm;  // bins + 1
  std::vector<double> mDensity;  // per nm, integrates to 1
  std::vector<double> mCdf;      // at the edges
};

}  // namespace prism

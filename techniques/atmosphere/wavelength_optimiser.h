// García Liñán's four-wavelength sky, fitted offline: λ₁..λ₄ and weights w₁..w₄ (XYZ = M·L with
// M[c][i] = c̄(λᵢ)·wᵢ) minimising the weighted mean squared CIELAB error (ΔE*ab²) against the
// reference sky over many view directions and sun elevations, each elevation exposed as in
// sky_evaluation.h and weighted (low sun counts more, so that the blue daytime sky does not
// dominate). A coarse grid search over the wavelengths (the weights of each combination by
// linear least squares in exposed XYZ) seeds Nelder–Mead (NLopt) over all eight parameters.
// Beyond the original, the full 3×4 matrix M (12 parameters) is then refined from the 8-parameter
// M for the same wavelengths, with the same objective.
#pragma once

#include <vector>

#include "techniques/atmosphere/sky_evaluation.h"

namespace prism::atmosphere {

struct OptimiserSettings {
  double gridStepNm = 20.0;          // wavelengths of the grid: 380, 400, ... 740 nm
  int seeds = 3;                     // best grid points refined by Nelder–Mead
  int maxEvaluations8 = 4000;
  int maxEvaluations12 = 8000;
  double lowSunWeight = 3.0;         // weight of sun elevations ≤ 10°, others 1
};

struct OptimiserResult {
  OptimisedWavelengths set;
  double gridObjective = 0.0;  // the best grid point's weighted mean ΔE*ab²
  double objective8 = 0.0;     // after Nelder–Mead, 8 parameters
  double objective12 = 0.0;    // the 12-parameter matrix
  int evaluations = 0;
};

OptimiserResult optimiseWavelengths(const SkySamples& samples, const SpectralSky& reference,
                                    const OptimiserSettings& settings, const Progress& progress = {});

}  // namespace prism::atmosphere

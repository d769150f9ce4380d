// Optimised wavelength sets for surfaces (issue 16): n wavelengths λ₁..λₙ and a full 3 × n matrix
// M, tristimulus ≈ M · (L(λ₁) … L(λₙ)), fitted for a given set of lights so that one frame of n
// wavelengths shows surfaces' colours as the 1 nm integral does. García Liñán's method, which
// Prism uses for the sky (techniques/atmosphere/wavelength_optimiser.h), generalised from one sky
// to surfaces: the training set is every reflectance given (the ColorChecker, reflectances
// spread over the gamut, the scene's own) under every light given, each light alone.
//
// Fit, deterministic:
// - For fixed wavelengths M is linear least squares in CIELAB's own coordinates, linearised: each
//   channel's residual is weighted by the derivative of CIELAB's f(t) = t^⅓ at the true value
//   (relative to the light's white), so a dark patch's error counts as much as CIELAB says, and
//   the three rows of M are three small n × n solves.
// - The wavelengths, whole nanometres, by coordinate descent on the objective, the mean ΔE00 over
//   the training set: each λᵢ in turn tries every whole nm between its neighbours and keeps the
//   best; sweeps repeat until none improves. Started from the uniform grid's midpoints and from the
//   lights' pdf quantiles (spectral/wavelength_pdf.h), and for n = 4 also from the best point of a
//   20 nm grid over all combinations; the best result wins.
// Not unbiased: accumulating frames does not converge beyond it (Rotated and Lights do).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/spectrum.h"

namespace prism {

struct FittedWavelengths {
  std::vector<double> lambdaNm;                       // n, ascending, whole nm
  Eigen::Matrix<double, 3, Eigen::Dynamic> weights;  // 3 × n, nm: tristimulus += weights · L
};

inline constexpr int kMaxFittedWavelengths = 64;  // beyond it a uniform grid is as close, and fits slow down

struct WavelengthFitProblem {
  std::vector<Spectrum> lights;        // each light's SPD (any scale), fitted alone
  std::vector<Spectrum> reflectances;  // the training surfaces
  int count = 16;                      // n, a multiple of 4 within 4–kMaxFittedWavelengths
  // The range: the wavelengths lie in it, and the truth is the integral over it alone (what the
  // other strategies' frames estimate; the lights' whites too).
  double minNm = kLambdaMinNm;
  double maxNm = kLambdaMaxNm;
};

using FitProgress = std::function<void(std::size_t done, std::size_t total)>;

// Error when the problem has no light, no reflectance, or a count or range out of bounds, and when
// no set gives a finite error.
FittedWavelengths fitWavelengths(const WavelengthFitProblem& problem, const Observer& obs,
                                 const FitProgress& progress = {});

// The light as the 1 nm trapezoid rule (Spectrum::integral) integrates it over [minNm, maxNm]
// alone: zero beyond the range, the nodes at its ends weighed by the part of their intervals
// inside it. What a frame sampled within the range integrates, whatever its strategy, and so the
// truth it is measured against. Zeroing the nodes beyond it alone counted half a nanometre outside
// at each end (400 uniform wavelengths over 500–600 nm read 1.17 ΔE00 off that truth).
Spectrum lightWithinRange(const Spectrum& light, double minNm, double maxNm);

// The white a light's colours are put into CIELAB against, for the fit and every report of it: the
// light's XYZ under `obs`, each channel at least 1 % of its Y. A light that a channel all but
// misses (a far-red LED's Z, 1e-81 of its Y; a sodium line's CIE 1964 Z, 0) would otherwise weigh
// that channel's errors by 1/Z: past what the least squares can hold, or, beside other lights, so
// far past theirs that their fit of the channel was lost. Every light the tables use (D65,
// A, F2, F11, the LEDs) has each channel above 1 % of Y: the floor leaves them as they were.
Eigen::Vector3d fitWhite(const Spectrum& light, const Observer& obs);

// The mean and largest ΔE00 of a set over the problem's lights × reflectances (CIELAB relative to
// each light's perfect white, fitWhite; truth and white over the problem's range).
struct FitError {
  double mean = 0.0;
  double max = 0.0;
};
FitError fitError(const FittedWavelengths& set, const WavelengthFitProblem& problem, const Observer& obs);

// Reflectances spread over a colour space's gamut: the Jakob–Hanika albedos of a steps³ grid of
// linear RGB (0 … 1 each), from the space's table. The training set's general part.
std::vector<Spectrum> gamutReflectances(const RgbToSpectrumTable& table, int steps);

// The training set every fit starts from: the 24 ColorChecker patches and gamutReflectances(table,
// kFitGamutSteps); callers add their own surfaces.
inline constexpr int kFitGamutSteps = 7;
std::vector<Spectrum> standardTrainingReflectances(const RgbToSpectrumTable& table);

// fitWavelengths, cached: the set is read from cacheDirectory()/wavelengths/KEY.txt when there (KEY
// the FNV-1a hash of the problem, the observer's curves and the fit's version) and written there
// atomically when fitted. A damaged file is refitted.
FittedWavelengths cachedFitWavelengths(const WavelengthFitProblem& problem, const Observer& obs,
                                       const FitProgress& progress = {});
std::uint64_t fitKey(const WavelengthFitProblem& problem, const Observer& obs);

}  // namespace prism

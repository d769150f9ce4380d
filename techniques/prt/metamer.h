// Metamers on demand (Schwenk et al.'s "Metacow" test): for a reflectance r and an illuminant E,
// the metameric blacks b are the null space of the 3 × n matrix of E × colour-matching functions
// (Cohen & Kappauf 1982, "Metameric color stimuli, fundamental metamers, and Wyszecki's
// metameric blacks"); r + b has r's colour under E for every such b. Of those, we want the one
// that differs most from r under a second illuminant while staying a reflectance (in [0, 1]).
//
// b is piecewise linear on the 81 wavelengths of the 5 nm grid (380–780 nm, held constant beyond
// as Prism extends reflectances), so its colour under E is exactly W_E·b with W_E the grid's
// weights folded from the 1 nm integration weights. b = N z, N an orthonormal basis of W_E's null
// space (QR); SLSQP (NLopt) maximises CIEDE2000 under the second illuminant over z subject to
// 0 ≤ r + N z ≤ 1 at the grid wavelengths, from a dozen feasible starts (the problem is not
// concave), keeping the best feasible point seen.
#pragma once

#include <Eigen/Core>

#include "spectral/observer.h"
#include "spectral/spectrum.h"

namespace prism::prt {

struct Metamer {
  Spectrum reflectance;         // r + b on the 1 nm grid
  Eigen::VectorXd gridValues;   // r + b at the 81 grid wavelengths, in [0, 1]
  double targetDeltaE2000 = 0;  // ΔE00 between r and r + b under the second illuminant
};

// Error when r leaves [0, 1] at a grid wavelength or the match illuminant has no colour.
Metamer findMetamer(const Spectrum& reflectance, const Spectrum& matchIlluminant, const Spectrum& targetIlluminant,
                    const Observer& observer);

// CIEDE2000 between two reflectances under an illuminant, CIELAB relative to its white.
double reflectanceDeltaE2000(const Spectrum& a, const Spectrum& b, const Spectrum& illuminant, const Observer& observer);

}  // namespace prism::prt

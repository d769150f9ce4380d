// The wavelength half of spectral PRT: the 5 nm grid of the paper's reference (81 wavelengths,
// 380–780 nm), spectra sampled on it, and the spectral basis φ_1..φ_m found by the singular value
// decomposition of the scene's sampled spectra (Peercy 1993, "Linear color representations for
// full spectral rendering", §3; Schwenk, Kuijper & Bockholt, §3.2).
//
// Inner products on the grid are plain sums over the 81 samples; the 5 nm step is folded into the
// reflectance × colour-matching projections (R̂), so that Σ_j L̃_j R̂_j is the 5 nm Riemann sum of
// ∫ L f_r c̄ dλ with L replaced by its projection on the basis. Since the projection P is
// orthogonal, (PL)ᵀ(f_r c̄) = (PL)ᵀ(P f_r c̄): the error is ((I − P)L)ᵀ((I − P) f_r c̄), the
// product of what the basis misses of the light and of the reflectance.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "spectral/observer.h"
#include "spectral/spectrum.h"

namespace prism::prt {

inline constexpr int kGridWavelengths = 81;
inline constexpr double kGridMinNm = 380.0;
inline constexpr double kGridStepNm = 5.0;

double gridWavelengthNm(int i);
// All 81 of them, in order.
std::vector<double> gridWavelengthsNm();
// The spectrum's values at the 81 grid wavelengths.
Eigen::VectorXd sampleOnGrid(const Spectrum& spectrum);
// The observer's three curves at the grid wavelengths (81 × 3). A camera's are scaled as the
// renderer and the path tracer scale them (absoluteTristimulusScale, less the 683 lm/W that PRT's
// radiance does not carry), so that its G of D65 is CIE 1931's Y: raw, a white under a D65 sky of
// 1 000 cd/m² came out at G 849 through the Nikon D850 where the rest of the frame showed 1 000.
Eigen::MatrixXd observerOnGrid(const Observer& observer);

class SpectralBasis {
 public:
  // Each spectrum (81 samples) is one column, scaled to unit length first so that an illuminant
  // tabulated at 100 weighs as much as a reflectance below 1. Each group (an environment's SH
  // terms, and what a medium makes of them) is scaled as one, by its longest member: a term keeps
  // its share of the light, so a band that is nearly 0 (a constant map's bands 1–4) adds nothing
  // rather than a unit-length column of rounding noise — which took the SVD's leading functions and
  // left spectral PRT 4–9 % dim under uniform maps. At least one non-zero spectrum (Error otherwise).
  explicit SpectralBasis(const std::vector<Eigen::VectorXd>& spectra,
                         const std::vector<std::vector<Eigen::VectorXd>>& groups = {});

  // How many basis functions exist: min(81, number of spectra that are not black).
  int available() const { return static_cast<int>(mSingularValues.size()); }
  // The leading m left singular vectors (81 × m, orthonormal columns); m in 1..available().
  Eigen::MatrixXd leading(int m) const;
  const Eigen::VectorXd& singularValues() const { return mSingularValues; }
  // Σ_{j<m} σ_j² / Σ_j σ_j²: the fraction of the columns' energy the leading m functions keep.
  double capturedEnergy(int m) const;

 private:
  Eigen::MatrixXd mVectors;
  Eigen::VectorXd mSingularValues;
};

}  // namespace prism::prt

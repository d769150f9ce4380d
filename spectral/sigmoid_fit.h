// Fitting Jakob–Hanika sigmoid-polynomial coefficients to one RGB albedo.
//
// The target is the RGB colour's XYZ in its gamut, seen as CIELAB relative to the gamut's white
// (D65; CIE D60 for the ACES spaces). The model is Prism's upsampled reflectance (sigmoid.glsl:
// the sigmoid polynomial on [380, 730] nm, flat beyond), seen lit by that white illuminant
// through CIE 1931. Levenberg–Marquardt with an analytic Jacobian minimises the
// CIE76 distance between the two, as in Jakob & Hanika 2019 §4. Coefficients are solved on
// t = (λ − 360 nm)/470 nm for conditioning and returned for λ in nm (sigmoid.glsl's form).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <glm/vec3.hpp>

#include "spectral/colour_space.h"
#include "spectral/observer.h"

namespace prism {

struct SigmoidFit {
  glm::vec3 coeffs{0.0f};        // c0, c1, c2 for λ in nm
  Eigen::Vector3d normalised{};  // the same on t ∈ [0, 1], a seed for a neighbouring fit
  double deltaE76 = 0.0;         // residual CIE76 distance to the target
  int iterations = 0;
};

// The illuminant an RGB space's white stands for: D65, or CIE daylight at 6000 K for ACES. Built
// once; frame assembly asks for it every frame.
const Spectrum& gamutWhiteIlluminant(const RgbColourSpace& gamut);

class SigmoidFitter {
 public:
  SigmoidFitter(const RgbColourSpace& gamut, const Spectrum& illuminant, const Observer& obs);

  // linearRgb is an albedo: each channel clamped to [0, 1] first.
  SigmoidFit fit(const Eigen::Vector3d& linearRgb,
                 const Eigen::Vector3d& seed = Eigen::Vector3d::Zero()) const;
  // The CIE76 distance from linearRgb (clamped likewise) of given coefficients (λ in nm, as
  // SigmoidFit::coeffs): how well a stored fit still reproduces its colour.
  double deltaE76(const Eigen::Vector3d& linearRgb, const glm::vec3& coeffs) const;

 private:
  RgbColourSpace mGamut;
  std::vector<double> mT;                        // normalised, clamped wavelength of each distinct node
  std::vector<Eigen::Vector3d> mWeights;         // Σ node weight · illuminant · observer / ∫Sȳ there
  Eigen::Vector3d mWhiteXyz;                     // the lit perfect reflector
};

}  // namespace prism

// The atmosphere's ground truth: the model of atmosphere_model.glsl integrated numerically in
// double precision, independently of the real-time tables (no tables, no per-step closed form,
// no analytic shadow cylinder): composite Simpson over a substitution that crowds samples at the
// ray's densest point, thousands of samples per ray, the sun's optical depth integrated afresh
// at every sample, and the planet's shadow boundaries found by bisection on "does the sun's ray
// hit the ground". Tests hold the GPU's and the CPU's tables to it.
#pragma once

#include <array>

#include "techniques/atmosphere/atmosphere_parameters.h"

namespace prism::atmosphere {

using Channels = std::array<double, 4>;  // one value per wavelength of a batch

// Optical depth from radius rKm along zenith cosine mu to the top of the atmosphere.
Channels referenceOpticalDepth(const AtmosphereParameters& p, const std::array<double, 4>& lambdaNm,
                               double rKm, double mu);

// Single-scattered radiance (W·m⁻²·sr⁻¹·nm⁻¹) reaching a camera at radius rKm from the
// direction (zenith, azimuth from the sun), sun at zenith cosine muSun; no ground reflection,
// no multiple scattering, no sun disc.
Channels referenceSingleScattering(const AtmosphereParameters& p,
                                   const std::array<double, 4>& lambdaNm, double rKm,
                                   double muSun, double zenith, double azimuth);

}  // namespace prism::atmosphere

// The atmosphere's ground truth: the model of atmosphere_model.glsl integrated numerically in
// double precision, independently of the real-time tables (no tables, no per-step closed form,
// no analytic shadow cylinder): optical depth by composite Simpson over a substitution that
// crowds samples at the ray's densest point (1000 intervals per half ray), the view ray by the
// midpoint rule over 1000 crowded samples per piece, the sun's optical depth integrated afresh
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

// The same over the first maxDistanceKm of the view ray (or to where it leaves the atmosphere
// or meets the ground, if nearer), with the transmittance of that stretch: what an
// aerial-perspective froxel holds.
struct ReferenceSegment {
  Channels radiance{};
  Channels transmittance{};
};
ReferenceSegment referenceSingleScatteringTo(const AtmosphereParameters& p,
                                             const std::array<double, 4>& lambdaNm, double rKm,
                                             double muSun, double zenith, double azimuth,
                                             double maxDistanceKm);

}  // namespace prism::atmosphere

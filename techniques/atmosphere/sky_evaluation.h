// How close a wavelength strategy's sky comes to the reference: the sky's radiance over view
// directions covering the whole upper hemisphere (equal solid angle per direction) for a list of
// sun elevations, seen by a camera 100 m above the ground, turned into XYZ by the strategy and
// compared in CIEDE2000.
//
// Exposure and white. Skies differ by 10⁴ in luminance from noon to dusk, so each sun elevation
// is exposed as a camera would be: the reference's mean luminance over the directions maps to
// Y = 0.18 (middle grey), for the reference and the strategy alike; CIELAB's white is D65 at
// Y = 1. The sun's disc is not part of the sky here (it is one direction of 10⁵ sr⁻¹).
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "techniques/atmosphere/atmosphere_parameters.h"
#include "techniques/atmosphere/sky_strategy.h"

namespace prism::atmosphere {

using Progress = std::function<void(std::size_t done, std::size_t total)>;

struct SkySamples {
  double cameraAltitudeKm = 0.1;
  std::vector<double> sunElevationsDeg;
  std::vector<double> zenith, azimuth;  // rad; one entry per direction
  std::size_t size() const { return sunElevationsDeg.size() * zenith.size(); }
  // Sample index of (elevation e, direction d).
  std::size_t index(std::size_t e, std::size_t d) const { return e * zenith.size() + d; }
};

// zeniths × azimuths directions: cos(zenith) at the midpoints of equal bins over (0, 1],
// azimuth from the sun over (0, π) likewise (the sky is symmetric about the sun's plane).
SkySamples makeSkySamples(std::vector<double> sunElevationsDeg, int zeniths, int azimuths);

// XYZ (Y in cd/m²) of every sample under a strategy: each batch's tables once, then every sample.
std::vector<Eigen::Vector3d> skyTristimulus(const AtmosphereParameters& p, const SkyStrategy& strategy,
                                            const SkySamples& samples, const Progress& progress = {});

// Spectral radiance of every sample at the nodes of a reference strategy (for the optimiser,
// which interpolates it between nodes, 1 nm apart).
struct SpectralSky {
  std::vector<double> lambdaNm;  // the nodes
  std::vector<float> radiance;   // [sample][node]
  std::vector<Eigen::Vector3d> xyz;  // the reference's integration of it
  double at(std::size_t sample, double lambda) const;
};
SpectralSky spectralSky(const AtmosphereParameters& p, double stepNm, const SkySamples& samples,
                        const Progress& progress = {});

// The exposure of each sun elevation (see above), from the reference.
std::vector<double> exposures(const SkySamples& samples, const std::vector<Eigen::Vector3d>& reference);

struct ElevationError {
  double elevationDeg = 0.0;
  double meanDeltaE = 0.0;
  double maxDeltaE = 0.0;
};
// CIELAB of sky XYZ under an exposure, with CIELAB's white CIE D65 at Y = 1 (the optimiser's
// space too).
Eigen::Vector3d exposedLab(const Eigen::Vector3d& xyz, double exposure);

std::vector<ElevationError> compareSkies(const SkySamples& samples, const std::vector<Eigen::Vector3d>& test,
                                         const std::vector<Eigen::Vector3d>& reference);

}  // namespace prism::atmosphere

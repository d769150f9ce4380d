// Prism's spectral sky (techniques/atmosphere: Hillaire's tables with multiple scattering, the
// measured solar spectrum and ozone) as PRT's distant environment, at any sun position: what the
// sky makes of sunlight, seen from the scene's ground, at PRT's 81 wavelengths. The sky is
// tabulated on an equirectangular grid of directions (z up, as PRT's frame; row 0 at the
// zenith), each texel the sky's radiance along its centre (below the horizon, the ground the sun
// lights), and projected on SH-5 with each texel's exact solid angle, as a map is; the sun's disc,
// which a grid cannot hold, is a delta of the solar irradiance that reaches the ground, projected
// exactly. Absolute units: W·m⁻²·sr⁻¹·nm⁻¹ (the sun W·m⁻²·nm⁻¹), so the sky needs no luminance.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/prt/prt_evaluation.h"

namespace prism::prt {

struct PrtSky {
  atmosphere::AtmosphereSky atmosphere;  // the planet, the sun's position, the ground's altitude
  bool sunDisc = true;                       // the sun itself, besides the sky it lights
};

inline constexpr int kSkyGridWidth = 128, kSkyGridHeight = 64;

struct SkyRadianceGrid {
  int width = 0, height = 0;
  std::vector<float> radiance;         // [texel y·width + x][kGridWavelengths]
  glm::dvec3 sunDirection{0, 0, 1};    // PRT's frame (z up), towards the sun
  std::vector<double> sunIrradiance;   // kGridWavelengths, on a surface facing the sun; 0 below the horizon
  // The radiance of the texel holding a direction (PRT's frame), linear between grid wavelengths.
  double radianceAt(const glm::dvec3& direction, double lambdaNm) const;
  double sunIrradianceAt(double lambdaNm) const;  // linear between grid wavelengths
};

// The sky of `sky` (its sun's disc or not: the grid holds both) on a width × height grid: 11
// batches of the atmosphere's tables over one integration of its transmittance densities
// (atmosphere_tables.h), every texel in parallel (~0.6 s on 2 cores).
SkyRadianceGrid tabulateSky(const PrtSky& sky, int width = kSkyGridWidth, int height = kSkyGridHeight);

// The grid as a PRT environment: its texels (each integrated over its solid angle, as the path
// tracer sees it: piecewise constant) and, with sunDisc, its sun; every value times `scale`.
SpectralEnvironment skyEnvironment(std::string name, const SkyRadianceGrid& grid, bool sunDisc, double scale);

// The sun's direction in PRT's frame (z up) for the atmosphere's elevation and azimuth.
glm::dvec3 prtSunDirection(const atmosphere::AtmosphereSky& atmosphere);

// The sun's elevation (degrees, negative) below which no sunlit air is in view from the ground:
// the planet's shadow covers all the atmosphere the eye can reach, the horizon's ray grazing the
// ground included (−(acos(Rb/r) + 2·acos(Rb/Rt)): −15.7° for Earth's 6360 and 6420 km at the
// ground). Below it the sky holds only the extrapolated tail of the multiple-scattering table,
// which Hillaire's model is not made for: white Y 1.9e-11 at −24° and 4.5e-17 at −27° against 82
// at 30°, 99.9 % of the grid exactly 0 at −27°, and the PRT report's errors erratic there.
double sunlitAirLimitDeg(const atmosphere::AtmosphereSky& atmosphere);

}  // namespace prism::prt

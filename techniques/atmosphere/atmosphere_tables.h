// Hillaire's tables for one batch of four wavelengths, computed on the CPU by the same shared
// code the GPU's compute passes run (shaders/shared/atmosphere_luts.glsl): the renderer's twin
// in tests, and the engine of `prism atmosphere evaluate|optimise`, which needs the sky of
// every strategy without a GPU.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/atmosphere/atmosphere_layout.h"

namespace prism::atmosphere {

struct AtmosphereTables {
  shared::GpuAtmosphere atmosphere{};
  std::vector<glm::vec4> transmittance;       // optical depth, width × height, x fastest
  std::vector<glm::vec4> multipleScattering;  // Ψ_ms, size × size; empty when it is off
};

// Both tables (multiple scattering only when the atmosphere asks for it), rows in parallel.
AtmosphereTables computeTables(const shared::GpuAtmosphere& atmosphere, unsigned threads = 0);

// The transmittance table without its wavelengths: per texel the optical depths of Rayleigh, Mie
// and ozone at unit coefficients (x, y, z; w 0). Optical depth is linear in the coefficients, so
// every batch's table of one atmosphere is their combination: computed once, it spares each
// further batch the table's integration (~90 % of a batch's time on the CPU; what tabulating many
// wavelengths, as PRT's spectral sky does, spends). Any batch of the atmosphere gives its shape.
// The shared unitCoefficientAtmosphere and transmittanceFromDensities (atmosphere_luts.glsl), as
// the GPU's pass combines its tables.
std::vector<glm::vec4> transmittanceDensities(const shared::GpuAtmosphere& atmosphere, unsigned threads = 0);
// computeTables with the transmittance table combined from those densities (equal to the direct
// integration up to float reassociation, ~1e-7 relative).
AtmosphereTables computeTables(const shared::GpuAtmosphere& atmosphere, const std::vector<glm::vec4>& densities,
                               unsigned threads = 0);

// Radiance from one direction, integrated along the view ray (not looked up in a sky-view
// table), sun disc excluded; withGround adds the ground's reflection below the horizon.
glm::vec4 skyRadiance(const AtmosphereTables& tables, float rKm, float muSun, float zenith,
                      float azimuth, bool withGround = true);

// Transmittance from radius rKm to space along a direction of zenith cosine mu (the sun's light
// reaching that point, per channel); 0 where the planet is in the way.
glm::vec4 transmittanceToSpace(const AtmosphereTables& tables, float rKm, float mu);

// The view direction of sky-view texel (x, y) for a camera at radius rKm.
struct SkyViewDirection {
  float zenith = 0.0f;
  float azimuth = 0.0f;  // from the sun's vertical plane
};
SkyViewDirection skyViewTexelDirection(const shared::GpuAtmosphere& atmosphere, float rKm, int x, int y);
// The sky-view table's coordinates ∈ [0, 1]² of a direction (the lookups' mapping).
glm::vec2 skyViewCoordinatesOf(const shared::GpuAtmosphere& atmosphere, float rKm, float zenith, float azimuth);

}  // namespace prism::atmosphere

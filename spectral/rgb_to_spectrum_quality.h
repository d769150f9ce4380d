// How well an upsampling table reproduces colours: CIEDE2000 between a target RGB albedo and
// its upsampled reflectance seen under the gamut's white illuminant through CIE 1931, both as
// CIELAB relative to that white.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "spectral/rgb_to_spectrum_table.h"

namespace prism {

struct UpsamplingError {
  std::size_t count = 0;
  double rmsDeltaE2000 = 0.0;
  double maxDeltaE2000 = 0.0;
  double fractionWithin1 = 0.0;  // share of colours with ΔE00 ≤ 1
  glm::vec3 worstRgb{0.0f};
  double minReflectance = 1.0;   // over all spectra, 360–830 nm
  double maxReflectance = 0.0;
};

// Every node of the table, coefficients as stored (no interpolation).
UpsamplingError nodeError(const RgbToSpectrumTable& table, unsigned threads = 0);

// Filtered8Bit: the filtered path with the 8-bit blend weights of common GPUs.
enum class LookupPath { Manual, Filtered, Filtered8Bit };
// Given albedos in the table's gamut through a run-time lookup path.
UpsamplingError lookupError(const RgbToSpectrumTable& table, LookupPath path,
                            std::span<const glm::vec3> rgbs, unsigned threads = 0);
// `samples` uniformly random linear albedos in the gamut (seeded, reproducible) through a
// run-time lookup path.
UpsamplingError roundTripError(const RgbToSpectrumTable& table, LookupPath path,
                               std::size_t samples, std::uint32_t seed, unsigned threads = 0);

}  // namespace prism

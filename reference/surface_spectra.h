// A surface's material at a path's four wavelengths, as the reference path tracer reads it at a
// hit: what it reflects (a base colour upsampled by the Jakob–Hanika table, a measured
// reflectance, a spectral texture, or a conductor's n and k) and what it emits (its own spectrum,
// or glTF's colour as a light's).
#pragma once

#include <glm/glm.hpp>

#include "reference/surface_hit.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/spectrum.h"

namespace prism::reference {

struct SurfaceSpectra {
  glm::vec4 albedoOrN{0.0f};  // the albedo, or a conductor's n
  glm::vec4 k{0.0f};          // a conductor's k; 0 otherwise
};
// `coefficients`: the untextured base colour's Jakob–Hanika coefficients in `table` (a textured
// one is upsampled here, per hit).
SurfaceSpectra surfaceSpectra(const SurfaceHit& hit, const Material& m, const glm::vec3& coefficients,
                              const RgbToSpectrumTable& table, const glm::vec4& lambdaNm);

// The radiance the surface emits (0 where its material emits none): its own spectrum times its
// luminance, or glTF's colour upsampled as a light's (RgbUnboundedSpectrum) times `emissionWhite`,
// the colour space's white of luminance 1, times its emissive luminance.
glm::vec4 emittedRadiance(const SurfaceHit& hit, const Material& m, const RgbToSpectrumTable& table,
                          const Spectrum& emissionWhite, const glm::vec4& lambdaNm);

}  // namespace prism::reference

#include "scene/scene_spectra.h"

#include <glm/vec4.hpp>

#include "shared_cpp.h"

namespace prism::shared {
#include "brdf.glsl"
}  // namespace prism::shared

namespace prism {

RgbIlluminantSpectrum backgroundRadiance(const Scene& scene, const RgbColourSpace& space,
                                         const RgbToSpectrumTable& table) {
  return RgbIlluminantSpectrum(table, space, scene.background, scene.backgroundLuminance);
}

Spectrum normalIncidenceReflectance(const ConductorIor& ior) {
  Spectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    glm::vec4 n(static_cast<float>(ior.n[i])), k(static_cast<float>(ior.k[i]));
    r[i] = shared::conductorFresnel(n, k, 1.0f).x;
  }
  return r;
}

}  // namespace prism

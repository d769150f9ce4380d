#include "reference/surface_spectra.h"

#include <Eigen/Core>

#include "shared_cpp.h"
#include "spectral/rgb_intent.h"
#include "spectral/spectral_texture.h"

namespace prism::shared {
#include "sigmoid.glsl"
}  // namespace prism::shared

namespace prism::reference {

SurfaceSpectra surfaceSpectra(const SurfaceHit& hit, const Material& m, const glm::vec3& coefficients,
                              const RgbToSpectrumTable& table, const glm::vec4& lambdaNm) {
  SurfaceSpectra s;
  if (m.conductor) {
    for (int j = 0; j < 4; ++j) {
      s.albedoOrN[j] = static_cast<float>(m.conductor->n.at(lambdaNm[j]));
      s.k[j] = static_cast<float>(m.conductor->k.at(lambdaNm[j]));
    }
  } else if (m.reflectance) {
    for (int j = 0; j < 4; ++j) s.albedoOrN[j] = static_cast<float>(m.reflectance->at(lambdaNm[j]));
  } else if (m.spectralTexture) {
    const Eigen::VectorXd c = sampleTexels(*m.spectralTexture, hit.uv);
    for (int j = 0; j < 4; ++j) s.albedoOrN[j] = static_cast<float>(reflectanceAt(*m.spectralTexture, c, lambdaNm[j]));
  } else {
    const glm::vec3 c = m.baseColourTexture >= 0 ? RgbAlbedoSpectrum(table, hit.albedo).coefficients() : coefficients;
    s.albedoOrN = shared::upsampledReflectance4(c, lambdaNm);
  }
  return s;
}

glm::vec4 emittedRadiance(const SurfaceHit& hit, const Material& m, const RgbToSpectrumTable& table,
                          const Spectrum& emissionWhite, const glm::vec4& lambdaNm) {
  glm::vec4 e(0.0f);
  if (m.emission)
    for (int j = 0; j < 4; ++j) e[j] = static_cast<float>(m.emission->spd.at(lambdaNm[j])) * m.emission->luminance;
  if (m.emitsRgb()) {
    const RgbUnboundedSpectrum colour(table, hit.emission);
    for (int j = 0; j < 4; ++j)
      e[j] = colour.at(lambdaNm[j]) * static_cast<float>(emissionWhite.at(lambdaNm[j])) * m.emissiveLuminance;
  }
  return e;
}

}  // namespace prism::reference

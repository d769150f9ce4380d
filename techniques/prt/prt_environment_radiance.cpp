#include "techniques/prt/prt_environment_radiance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "shared_cpp.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/rgb_intent.h"
#include "spectral/sigmoid_fit.h"
#include "techniques/prt/prt_evaluation.h"

namespace prism::prt {
namespace {

// A map's texels as spectra (per unit of the section's scale) and, when first asked for, their
// radiance over the sky: what the environment's rotation about the zenith and its luminance leave
// alone. A texel is light, the illuminant intent: the map's white times its unbounded spectrum
// (held apart, 16 bytes a texel).
struct MapSpectra {
  Spectrum white;  // the colour space's white illuminant (D65)
  std::vector<RgbUnboundedSpectrum> texels;
  mutable std::once_flag summed;
  mutable Spectrum fromAbove;  // Σ over the texels above the horizon of their radiance × solid angle there
};

// Texel (x, y) covers the part of its solid angle above the horizon, (2π/width)·(max(cos θ₀, 0) −
// max(cos θ₁, 0)); the sum runs at every 5 nm, linear between (texels' spectra are smooth).
Spectrum sumAboveHorizon(const MapSpectra& map, int w, int h) {
  std::vector<double> lambdasNm, sums;
  for (int lambdaNm = kLambdaMinNm; lambdaNm <= kLambdaMaxNm; lambdaNm += 5) lambdasNm.push_back(lambdaNm);
  sums.assign(lambdasNm.size(), 0.0);
  for (int y = 0; y < h; ++y) {
    const double cos0 = std::cos(std::numbers::pi * y / h), cos1 = std::cos(std::numbers::pi * (y + 1) / h);
    const double above = std::max(cos0, 0.0) - std::max(cos1, 0.0);
    if (above <= 0.0) break;  // rows run from the zenith down
    const double solidAngle = 2.0 * std::numbers::pi / w * above;
    for (int x = 0; x < w; ++x) {
      const RgbUnboundedSpectrum& texel = map.texels[static_cast<std::size_t>(y * w + x)];
      for (std::size_t i = 0; i < lambdasNm.size(); ++i) sums[i] += solidAngle * texel.at(static_cast<float>(lambdasNm[i]));
    }
  }
  return map.white * TabulatedSpectrum(std::move(lambdasNm), std::move(sums), Extrapolation::Clamp).toDense();
}

// The last map's spectra, kept for the process (16 bytes a texel: a 4K map's hold about 130 MB
// until another map replaces them): every change of a scene with a PRT map under water asks for
// its sum (about 20 ms for a 256 × 128 map; 256 times that, by its texel count, for 4K), and the PRT panel's rotation and luminance sliders change
// the scene on every frame of a drag. Keyed by the map's identity (the section shares it between
// copies of the scene) and the table's.
std::shared_ptr<const MapSpectra> mapSpectra(const std::shared_ptr<const PrtMap>& map, const RgbToSpectrumTable& table) {
  static std::mutex mutex;
  static std::weak_ptr<const PrtMap> lastMap;
  static const RgbToSpectrumTable* lastTable = nullptr;
  static std::uint32_t lastTableHash = 0;
  static std::shared_ptr<const MapSpectra> last;
  std::lock_guard lock(mutex);
  if (last && lastMap.lock() == map && lastTable == &table && lastTableHash == table.inputsHash()) return last;
  auto spectra = std::make_shared<MapSpectra>();
  spectra->white = gamutWhiteIlluminant(colourSpace(table.gamut()));
  spectra->texels.reserve(map->linearRgb.size() / 3);
  for (std::size_t i = 0; i < map->linearRgb.size(); i += 3)
    spectra->texels.emplace_back(table, glm::vec3(map->linearRgb[i], map->linearRgb[i + 1], map->linearRgb[i + 2]));
  lastMap = map;
  lastTable = &table;
  lastTableHash = table.inputsHash();
  last = spectra;
  return spectra;
}

class SectionEnvironment final : public TechniqueEnvironment {
 public:
  SectionEnvironment(const PrtSection& section, const RgbToSpectrumTable& table) : mMap(section.map) {
    // World (y-up) to PRT's frame (z-up, prt_scene_mesh.h), then the environment turned by R is
    // L(Rᵀω) (rotateEnvironment's convention).
    const glm::dmat3 zUp(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0);  // columns: x→x, y→z, z→−y
    const glm::dmat3 rotation(glm::rotate(glm::dmat4(1.0), glm::radians(static_cast<double>(section.rotationDeg)),
                                          glm::dvec3(0.0, 0.0, 1.0)));
    mToEnvironment = glm::transpose(rotation) * zUp;
    if (section.sky) {
      mSky = sectionSky(*section.sky);  // radiance in W·m⁻²·sr⁻¹·nm⁻¹ already; its sun is a light
    } else if (mMap) {
      mSpectra = mapSpectra(mMap, table);
      mScale = section.luminanceCdM2 /
               gridLuminance(mSpectra->white * RgbUnboundedSpectrum(table, glm::vec3(1.0f)).toDense()) /
               double(shared::kLumensPerWatt);
    } else {
      mSpd = illuminant(section.illuminant);
      // PRT's spectra are scaled so that ∫ L ȳ dλ on its grid is the luminance; the path tracer's
      // are radiance, whose luminance carries 683 lm/W.
      mSpd *= section.luminanceCdM2 / gridLuminance(mSpd) / double(shared::kLumensPerWatt);
      mUniform = section.shape == "uniform";
    }
  }

  double radiance(const glm::vec3& directionW, double lambdaNm) const override {
    const glm::dvec3 d = glm::normalize(mToEnvironment * glm::dvec3(directionW));
    if (mSky) return mSky->radianceAt(d, lambdaNm);
    if (!mMap) {
      const double spd = mSpd.at(lambdaNm);
      if (mUniform) return spd;
      return spd * skyGradient(d.z);  // skyGradientEnvironment's, with its default ground
    }
    const glm::ivec2 t = equirectangularTexelOf(d, mMap->width, mMap->height);
    const int x = t.x, y = t.y;
    return mScale * mSpectra->white.at(lambdaNm) *
           static_cast<double>(
               mSpectra->texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(mMap->width) + static_cast<std::size_t>(x)]
                   .at(static_cast<float>(lambdaNm)));
  }

  // Exact, whatever the rotation about the zenith: the uniform sky 2π·L, the overcast gradient
  // 2π·L_z·∫₀¹ (1 + 2μ)/3 dμ = 4π·L_z/3, a map its texels' sum (sumAboveHorizon, made once per
  // map); the spectral sky by the default quadrature.
  Spectrum scalarIrradianceFromAbove() const override {
    if (mSky) return TechniqueEnvironment::scalarIrradianceFromAbove();
    if (!mMap) return mSpd * (mUniform ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi / 3.0);
    const MapSpectra& m = *mSpectra;
    std::call_once(m.summed, [&] { m.fromAbove = sumAboveHorizon(m, mMap->width, mMap->height); });
    return m.fromAbove * mScale;
  }

 private:
  std::shared_ptr<const PrtMap> mMap;
  std::shared_ptr<const SkyRadianceGrid> mSky;
  glm::dmat3 mToEnvironment{1.0};
  Spectrum mSpd;
  bool mUniform = false;
  std::shared_ptr<const MapSpectra> mSpectra;
  double mScale = 1.0;
};

}  // namespace

std::shared_ptr<const TechniqueEnvironment> environmentRadiance(const PrtSection& section, const RgbToSpectrumTable& table) {
  return std::make_shared<SectionEnvironment>(section, table);
}

}  // namespace prism::prt

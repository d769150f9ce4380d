#include "techniques/atmosphere/atmosphere_tables.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_for.h"

namespace prism::shared {

// atmosphere_luts.glsl compiled inside a class whose members are its accessors.
class AtmosphereTablesKernel {
 public:
  explicit AtmosphereTablesKernel(const atmosphere::AtmosphereTables& tables) : mTables(tables) {}

  vec4 transmittanceLutTexel(int, int x, int y) const {
    return mTables.transmittance[static_cast<std::size_t>(y * kTransmittanceLutWidth + x)];
  }
  vec4 multipleScatteringLutTexel(int, int x, int y) const {
    if (mTables.multipleScattering.empty()) return vec4(0.0f);
    return mTables.multipleScattering[static_cast<std::size_t>(y * kMultipleScatteringLutSize + x)];
  }

#include "atmosphere_luts.glsl"

 private:
  const atmosphere::AtmosphereTables& mTables;
};

}  // namespace prism::shared

namespace prism::atmosphere {

using shared::AtmosphereTablesKernel;

namespace {

// The multiple-scattering table over a finished transmittance table, when the atmosphere asks for it.
void computeMultipleScattering(AtmosphereTables& tables, unsigned threads) {
  if (tables.atmosphere.options.x <= 0.5f) return;
  AtmosphereTablesKernel kernel(tables);
  const int n = shared::kMultipleScatteringLutSize;
  std::vector<glm::vec4> ms(static_cast<std::size_t>(n * n));
  parallelFor(static_cast<std::size_t>(n), threads, [&](std::size_t y) {
    for (int x = 0; x < n; ++x) {
      ms[y * static_cast<std::size_t>(n) + static_cast<std::size_t>(x)] =
          kernel.multipleScatteringLutValue(tables.atmosphere, 0, x, static_cast<int>(y));
    }
  });
  tables.multipleScattering = std::move(ms);
}

std::vector<glm::vec4> transmittanceTexels(const shared::GpuAtmosphere& atmosphere, unsigned threads) {
  AtmosphereTables none;
  AtmosphereTablesKernel kernel(none);
  const int tw = shared::kTransmittanceLutWidth, th = shared::kTransmittanceLutHeight;
  std::vector<glm::vec4> texels(static_cast<std::size_t>(tw * th));
  parallelFor(static_cast<std::size_t>(th), threads, [&](std::size_t y) {
    for (int x = 0; x < tw; ++x) {
      texels[y * static_cast<std::size_t>(tw) + static_cast<std::size_t>(x)] =
          kernel.transmittanceLutValue(atmosphere, x, static_cast<int>(y));
    }
  });
  return texels;
}

}  // namespace

AtmosphereTables computeTables(const shared::GpuAtmosphere& atmosphere, unsigned threads) {
  AtmosphereTables tables;
  tables.atmosphere = atmosphere;
  tables.transmittance = transmittanceTexels(atmosphere, threads);
  computeMultipleScattering(tables, threads);
  return tables;
}

std::vector<glm::vec4> transmittanceDensities(const shared::GpuAtmosphere& atmosphere, unsigned threads) {
  AtmosphereTables none;
  return transmittanceTexels(AtmosphereTablesKernel(none).unitCoefficientAtmosphere(atmosphere), threads);
}

AtmosphereTables computeTables(const shared::GpuAtmosphere& atmosphere, const std::vector<glm::vec4>& densities,
                               unsigned threads) {
  AtmosphereTables tables;
  tables.atmosphere = atmosphere;
  AtmosphereTablesKernel kernel(tables);
  tables.transmittance.resize(densities.size());
  for (std::size_t i = 0; i < densities.size(); ++i)
    tables.transmittance[i] = kernel.transmittanceFromDensities(atmosphere, densities[i]);
  computeMultipleScattering(tables, threads);
  return tables;
}

glm::vec4 skyRadiance(const AtmosphereTables& tables, float rKm, float muSun, float zenith,
                      float azimuth, bool withGround) {
  AtmosphereTablesKernel kernel(tables);
  glm::vec3 d(std::sin(zenith) * std::cos(azimuth), std::cos(zenith), std::sin(zenith) * std::sin(azimuth));
  return kernel.skyRadiance(tables.atmosphere, 0, rKm, muSun, d, withGround);
}

glm::vec4 transmittanceToSpace(const AtmosphereTables& tables, float rKm, float mu) {
  AtmosphereTablesKernel kernel(tables);
  return kernel.transmittanceToSpace(tables.atmosphere, 0, rKm, mu);
}

SkyViewDirection skyViewTexelDirection(const shared::GpuAtmosphere& atmosphere, float rKm, int x, int y) {
  AtmosphereTables none;
  AtmosphereTablesKernel kernel(none);
  glm::vec2 unit(float(x) / float(shared::kSkyViewLutWidth - 1), float(y) / float(shared::kSkyViewLutHeight - 1));
  glm::vec3 d = kernel.skyViewDirection(atmosphere, rKm, unit);
  return {static_cast<float>(std::acos(std::clamp(double(d.y), -1.0, 1.0))),
          static_cast<float>(std::atan2(double(d.z), double(d.x)))};
}

glm::vec2 skyViewCoordinatesOf(const shared::GpuAtmosphere& atmosphere, float rKm, float zenith, float azimuth) {
  AtmosphereTables none;
  AtmosphereTablesKernel kernel(none);
  return kernel.skyViewCoordinates(atmosphere, rKm, std::cos(zenith), std::cos(azimuth));
}

}  // namespace prism::atmosphere

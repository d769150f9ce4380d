#include "techniques/prt/prt_sky.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/parallel_for.h"
#include "techniques/atmosphere/atmosphere_tables.h"
#include "techniques/prt/prt_spectra.h"
#include "techniques/prt/sh_tools.h"

namespace prism::prt {
namespace {

double onGrid(const std::vector<double>& values, double lambdaNm) {
  double t = std::clamp((lambdaNm - kGridMinNm) / kGridStepNm, 0.0, kGridWavelengths - 1.0);
  int i = std::min(static_cast<int>(t), kGridWavelengths - 2);
  return (1.0 - (t - i)) * values[static_cast<std::size_t>(i)] + (t - i) * values[static_cast<std::size_t>(i) + 1];
}

}  // namespace

glm::dvec3 prtSunDirection(const atmosphere::AtmosphereSky& atmosphere) {
  const glm::dvec3 w(atmosphere.sunDirection());  // world, y up
  return glm::normalize(glm::dvec3(w.x, -w.z, w.y));  // x→x, y→z, z→−y (prt_scene_mesh.h)
}

double sunlitAirLimitDeg(const atmosphere::AtmosphereSky& atmosphere) {
  const double bottom = atmosphere.parameters.bottomRadiusKm, top = atmosphere.parameters.topRadiusKm;
  return -glm::degrees(std::acos(bottom / atmosphere.originKm()) + 2.0 * std::acos(bottom / top));
}

double SkyRadianceGrid::radianceAt(const glm::dvec3& direction, double lambdaNm) const {
  const glm::ivec2 t = equirectangularTexelOf(direction, width, height);
  const std::size_t texel = static_cast<std::size_t>(t.y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(t.x);
  double u = std::clamp((lambdaNm - kGridMinNm) / kGridStepNm, 0.0, kGridWavelengths - 1.0);
  int i = std::min(static_cast<int>(u), kGridWavelengths - 2);
  const float* row = radiance.data() + texel * kGridWavelengths;
  return (1.0 - (u - i)) * row[i] + (u - i) * row[i + 1];
}

double SkyRadianceGrid::sunIrradianceAt(double lambdaNm) const { return onGrid(sunIrradiance, lambdaNm); }

SkyRadianceGrid tabulateSky(const PrtSky& sky, int width, int height) {
  const atmosphere::AtmosphereSky& a = sky.atmosphere;
  SkyRadianceGrid grid;
  grid.width = width;
  grid.height = height;
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  grid.radiance.assign(texels * kGridWavelengths, 0.0f);
  grid.sunIrradiance.assign(kGridWavelengths, 0.0);
  grid.sunDirection = prtSunDirection(a);
  const float rKm = static_cast<float>(a.originKm());
  const float muSun = static_cast<float>(grid.sunDirection.z);
  const double sunAzimuth = std::atan2(grid.sunDirection.y, grid.sunDirection.x);
  // The solar spectrum and ozone's cross-section are data at 10 nm, linear between: the sky is
  // computed at every other grid wavelength (380, 390, …, 780 nm) and the ones between are the
  // mean of their neighbours.
  constexpr int kNodes = (kGridWavelengths + 1) / 2;
  // The transmittance table's integration once for all batches (atmosphere_tables.h).
  const std::vector<glm::vec4> densities =
      atmosphere::transmittanceDensities(atmosphere::packAtmosphere(a.parameters, glm::vec4(550.0f)));
  for (int first = 0; first < kNodes; first += 4) {
    glm::vec4 lambdaNm(0.0f);  // ≤ 0: an unused channel
    for (int j = 0; j < 4 && first + j < kNodes; ++j) lambdaNm[j] = static_cast<float>(gridWavelengthNm(2 * (first + j)));
    atmosphere::AtmosphereTables tables =
        atmosphere::computeTables(atmosphere::packAtmosphere(a.parameters, lambdaNm), densities);
    parallelFor(static_cast<std::size_t>(height), 0, [&](std::size_t y) {
      for (int x = 0; x < width; ++x) {
        EquirectangularTexel texel = equirectangularTexel(x, static_cast<int>(y), width, height);
        const glm::dvec3& d = texel.direction;
        float zenith = static_cast<float>(std::acos(std::clamp(d.z, -1.0, 1.0)));
        float azimuth = static_cast<float>(std::atan2(d.y, d.x) - sunAzimuth);
        glm::vec4 l = atmosphere::skyRadiance(tables, rKm, muSun, zenith, azimuth, true);
        float* row = grid.radiance.data() + (y * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * kGridWavelengths;
        for (int j = 0; j < 4 && first + j < kNodes; ++j) row[2 * (first + j)] = l[j];
      }
    });
    glm::vec4 t = atmosphere::transmittanceToSpace(tables, rKm, muSun);
    for (int j = 0; j < 4 && first + j < kNodes; ++j)
      grid.sunIrradiance[static_cast<std::size_t>(2 * (first + j))] = atmosphere::solarIrradiance(lambdaNm[j]) * t[j];
  }
  for (std::size_t texel = 0; texel < texels; ++texel) {
    float* row = grid.radiance.data() + texel * kGridWavelengths;
    for (int i = 1; i < kGridWavelengths; i += 2) row[i] = 0.5f * (row[i - 1] + row[i + 1]);
  }
  for (std::size_t i = 1; i < kGridWavelengths; i += 2)
    grid.sunIrradiance[i] = 0.5 * (grid.sunIrradiance[i - 1] + grid.sunIrradiance[i + 1]);
  return grid;
}

SpectralEnvironment skyEnvironment(std::string name, const SkyRadianceGrid& grid, bool sunDisc, double scale) {
  Eigen::MatrixXd projection = Eigen::MatrixXd::Zero(kGridWavelengths, 25);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const float* row = grid.radiance.data() +
                         (static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(x)) *
                             kGridWavelengths;
      Eigen::VectorXd spectrum = Eigen::Map<const Eigen::VectorXf>(row, kGridWavelengths).cast<double>();
      // Integrated over the texel, as a map's are: the sky as the piecewise-constant radiance it is.
      projection += spectrum * equirectangularTexelSh(x, y, grid.width, grid.height).transpose();
    }
  }
  // A delta of irradiance E at the sun: L̃_k = E·Y_k(sun).
  if (sunDisc)
    projection += Eigen::Map<const Eigen::VectorXd>(grid.sunIrradiance.data(), kGridWavelengths) *
                evaluateSh(grid.sunDirection).transpose();
  return gridEnvironment(std::move(name), projection * scale);
}

}  // namespace prism::prt

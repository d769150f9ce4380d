// The real-time tables (float, a few dozen samples per ray, shaders/shared/atmosphere_luts.glsl
// on the CPU) against the double-precision reference of the same model.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "techniques/atmosphere/atmosphere_reference.h"
#include "techniques/atmosphere/atmosphere_tables.h"

namespace prism::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;
const std::array<double, 4> kLambdas{360.0, 440.0, 550.0, 680.0};
// Transmittance is held to 1e-3 relative where it is at least 1e-6 (optical depth ≤ 13.8):
// deeper, float's rounding of the optical-depth sum (a few 1e-5 of τ) alone exceeds 1e-3 of T.
// The worst case everywhere is printed too.
constexpr double kDeepestOpticalDepth = 13.8155;

shared::GpuAtmosphere batchOf(const AtmosphereParameters& p) {
  return packAtmosphere(p, glm::vec4(360.0f, 440.0f, 550.0f, 680.0f));
}

TEST(AtmosphereTables, TransmittanceMatchesTheReference) {
  AtmosphereParameters p;
  AtmosphereTables tables = computeTables(batchOf(p), 0);
  double worst = 0.0, worstAll = 0.0;
  for (int y = 0; y < shared::kTransmittanceLutHeight; y += 3) {
    for (int x = 0; x < shared::kTransmittanceLutWidth; x += 5) {
      shared::RadiusCosine rc = shared::transmittanceLutParameters(
          tables.atmosphere, glm::vec2(float(x) / float(shared::kTransmittanceLutWidth - 1),
                                       float(y) / float(shared::kTransmittanceLutHeight - 1)));
      Channels ref = referenceOpticalDepth(p, kLambdas, rc.r, rc.mu);
      glm::vec4 depth = tables.transmittance[static_cast<std::size_t>(y * shared::kTransmittanceLutWidth + x)];
      for (int j = 0; j < 4; ++j) {
        double tauRef = ref[static_cast<std::size_t>(j)];
        double relative = std::abs(std::exp(-double(depth[j])) - std::exp(-tauRef)) / std::exp(-tauRef);
        worstAll = std::max(worstAll, relative);
        if (tauRef <= kDeepestOpticalDepth) worst = std::max(worst, relative);
      }
    }
  }
  std::printf("transmittance: max relative error %.3g where T >= 1e-6 (%.3g everywhere)\n", worst, worstAll);
  EXPECT_LE(worst, 1e-3);
}

// One integration of the unit densities serves every batch: its combination is the directly
// integrated table up to float reassociation, and so is the multiple scattering built on it.
TEST(AtmosphereTables, DensitiesCombineIntoEachBatchsTable) {
  AtmosphereParameters p;
  const std::vector<glm::vec4> densities = transmittanceDensities(batchOf(p));
  for (glm::vec4 lambdas : {glm::vec4(360.0f, 440.0f, 550.0f, 680.0f), glm::vec4(400.0f, 500.0f, 600.0f, 0.0f)}) {
    const shared::GpuAtmosphere batch = packAtmosphere(p, lambdas);
    const AtmosphereTables direct = computeTables(batch), combined = computeTables(batch, densities);
    ASSERT_EQ(combined.transmittance.size(), direct.transmittance.size());
    ASSERT_EQ(combined.multipleScattering.size(), direct.multipleScattering.size());
    double worst = 0.0;
    auto compare = [&](const glm::vec4& a, const glm::vec4& b) {
      for (int j = 0; j < 4; ++j) {
        const double scale = std::max(std::abs(double(b[j])), 1e-30);
        worst = std::max(worst, std::abs(double(a[j]) - double(b[j])) / scale);
      }
    };
    for (std::size_t i = 0; i < direct.transmittance.size(); ++i) compare(combined.transmittance[i], direct.transmittance[i]);
    for (std::size_t i = 0; i < direct.multipleScattering.size(); ++i)
      compare(combined.multipleScattering[i], direct.multipleScattering[i]);
    std::printf("tables from unit densities against direct integration: worst %.3g relative\n", worst);
    EXPECT_LE(worst, 1e-5);  // a few float roundings of sums of 160–320 steps
  }
}

TEST(AtmosphereTables, SingleScatteringMatchesTheReference) {
  AtmosphereParameters p;
  p.multipleScattering = false;
  AtmosphereTables tables = computeTables(batchOf(p), 0);
  const float r = float(p.bottomRadiusKm) + 0.2f;
  double worst = 0.0, worstAll = 0.0;
  for (double elevationDeg : {-2.0, 0.0, 5.0, 45.0}) {
    double muSun = std::sin(elevationDeg * kPi / 180.0);
    std::vector<Channels> want;
    std::vector<glm::vec4> got;
    for (double zenithDeg : {0.0, 45.0, 80.0, 89.0, 95.0}) {
      for (double azimuthDeg : {0.0, 30.0, 90.0, 180.0}) {
        double zenith = zenithDeg * kPi / 180.0, azimuth = azimuthDeg * kPi / 180.0;
        want.push_back(referenceSingleScattering(p, kLambdas, r, muSun, zenith, azimuth));
        got.push_back(skyRadiance(tables, r, float(muSun), float(zenith), float(azimuth), false));
      }
    }
    // Held where the sky is at least 1 % of its brightest sample at that wavelength (the dark
    // ultraviolet horizon under a setting sun is reported, not held).
    for (int j = 0; j < 4; ++j) {
      double peak = 0.0;
      for (const Channels& w : want) peak = std::max(peak, w[static_cast<std::size_t>(j)]);
      for (std::size_t k = 0; k < want.size(); ++k) {
        double w = want[k][static_cast<std::size_t>(j)];
        double relative = std::abs(double(got[k][j]) - w) / std::max(w, 1e-30);
        worstAll = std::max(worstAll, relative);
        if (w >= 0.01 * peak) worst = std::max(worst, relative);
      }
    }
  }
  std::printf("single scattering: max relative error %.3g where at least 1%% of the peak (%.3g everywhere)\n",
              worst, worstAll);
  EXPECT_LE(worst, 1e-3);
}

TEST(AtmosphereTables, SkyViewCoordinatesInvertTheTexelDirections) {
  AtmosphereParameters p;
  shared::GpuAtmosphere a = batchOf(p);
  double worst = 0.0;
  for (float altitude : {0.0016f, 0.2f, 10.0f}) {
    float r = float(p.bottomRadiusKm) + altitude;
    // Rows 0 and H − 1 are the zenith and the nadir, where every azimuth is the same direction.
    for (int y = 1; y + 1 < shared::kSkyViewLutHeight; ++y) {
      for (int x = 0; x < shared::kSkyViewLutWidth; x += 7) {
        SkyViewDirection d = skyViewTexelDirection(a, r, x, y);
        glm::vec2 unit = skyViewCoordinatesOf(a, r, d.zenith, d.azimuth);
        worst = std::max({worst, std::abs(double(unit.x) * (shared::kSkyViewLutWidth - 1) - x),
                          std::abs(double(unit.y) * (shared::kSkyViewLutHeight - 1) - y)});
      }
    }
  }
  std::printf("sky view: direction → coordinates round trip, max %.3g texels\n", worst);
  EXPECT_LE(worst, 0.02);
}

}  // namespace
}  // namespace prism::atmosphere

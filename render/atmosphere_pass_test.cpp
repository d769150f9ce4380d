// The sky's tables on the GPU (llvmpipe in CI) against the double-precision reference of the
// same model (techniques/atmosphere/atmosphere_reference.h) and against their CPU twin.
#include "techniques/atmosphere/gpu/atmosphere_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>

#include "core/worst_of.h"
#include "gpu/headless_context.h"
#include "techniques/atmosphere/atmosphere_texels.h"
#include "techniques/atmosphere/atmosphere_reference.h"
#include "techniques/atmosphere/atmosphere_tables.h"

namespace prism::render {
namespace {

using namespace prism::atmosphere;
constexpr double kPi = std::numbers::pi;
const std::array<double, 4> kLambdas{360.0, 440.0, 550.0, 680.0};
// Transmittance is held to 1e-3 relative where it is at least 1e-6 (optical depth ≤ 13.8):
// deeper, float's rounding of the optical-depth sum (a few 1e-5 of τ) alone exceeds 1e-3 of T.
// The worst case everywhere is printed too.
constexpr double kDeepestOpticalDepth = 13.8155;

// The pass's tables read back (stalls).
AtmosphereTexels readTexels(const AtmospherePass& pass) {
  return dynamic_cast<const AtmosphereTexels&>(*pass.readTexels());
}

TEST(AtmospherePass, TablesMatchTheDoublePrecisionReference) {
  gpu::HeadlessContext context;
  AtmosphereParameters p;
  p.multipleScattering = false;  // the sky view is then single scattering alone
  shared::GpuAtmosphere batch = packAtmosphere(p, glm::vec4(360.0f, 440.0f, 550.0f, 680.0f));
  const float r = float(p.bottomRadiusKm) + 0.2f;
  atmosphere::AtmospherePass pass;
  AtmosphereTables cpu = computeTables(batch);

  // Transmittance: every 5th × 3rd texel.
  atmosphere::AtmosphereView view;
  view.originKm = r;
  pass.update({batch}, view);
  std::vector<glm::vec4> depth = readTexels(pass).transmittance[0];
  double worst = 0.0, worstAll = 0.0, worstCpu = 0.0;
  for (int y = 0; y < shared::kTransmittanceLutHeight; y += 3) {
    for (int x = 0; x < shared::kTransmittanceLutWidth; x += 5) {
      std::size_t i = static_cast<std::size_t>(y * shared::kTransmittanceLutWidth + x);
      shared::RadiusCosine rc = shared::transmittanceLutParameters(
          batch, glm::vec2(float(x) / float(shared::kTransmittanceLutWidth - 1),
                           float(y) / float(shared::kTransmittanceLutHeight - 1)));
      Channels ref = referenceOpticalDepth(p, kLambdas, rc.r, rc.mu);
      for (int j = 0; j < 4; ++j) {
        double tauRef = ref[static_cast<std::size_t>(j)];
        double relative = std::abs(std::exp(-double(depth[i][j])) - std::exp(-tauRef)) / std::exp(-tauRef);
        worstAll = worstOf(worstAll, relative);
        if (tauRef <= kDeepestOpticalDepth) worst = worstOf(worst, relative);
        worstCpu = worstOf(worstCpu, std::abs(double(depth[i][j]) - double(cpu.transmittance[i][j])) /
                                          std::max(double(cpu.transmittance[i][j]), 1e-30));
      }
    }
  }
  std::printf("transmittance, GPU vs double reference: max relative %.3g where T >= 1e-6 (%.3g everywhere)\n",
              worst, worstAll);
  // The CPU twin is held to the same reference in atmosphere_test; the two differ by the
  // driver's exp() and summation order, and most where rays graze the atmosphere's top, where
  // float's r and μ move the path's length: 2.1e-4 on the top texel row, the same in all four
  // channels (a length, not a spectrum; the twin is within 1e-5 of the reference there). Held
  // within 5e-4, so that a formula changed on one side alone shows before it reaches the
  // reference's 1e-3.
  std::printf("transmittance, GPU vs CPU twin: max relative optical depth %.3g\n", worstCpu);
  EXPECT_LE(worst, 1e-3);
  EXPECT_LE(worstCpu, 5e-4);

  // Single scattering: sky-view texels above the horizon, for a low and a high sun.
  for (double elevationDeg : {5.0, 45.0}) {
    float muSun = float(std::sin(elevationDeg * kPi / 180.0));
    view.sun = glm::vec3(std::sqrt(1.0f - muSun * muSun), muSun, 0.0f);
    pass.update({batch}, view);
    std::vector<glm::vec4> sky = readTexels(pass).skyView[0];
    std::vector<std::array<double, 4>> got, want;
    for (int y = 2; y < shared::kSkyViewLutHeight / 2; y += 9) {
      for (int x = 0; x < shared::kSkyViewLutWidth; x += 37) {
        SkyViewDirection a = skyViewTexelDirection(batch, r, x, y);
        glm::vec4 g = sky[static_cast<std::size_t>(y * shared::kSkyViewLutWidth + x)];
        got.push_back({g.x, g.y, g.z, g.w});
        want.push_back(referenceSingleScattering(p, kLambdas, r, muSun, a.zenith, a.azimuth));
      }
    }
    double worstSky = 0.0, worstSkyAll = 0.0;
    for (int j = 0; j < 4; ++j) {
      double peak = 0.0;
      for (const auto& w : want) peak = std::max(peak, w[static_cast<std::size_t>(j)]);
      for (std::size_t k = 0; k < want.size(); ++k) {
        double w = want[k][static_cast<std::size_t>(j)];
        double relative = std::abs(got[k][static_cast<std::size_t>(j)] - w) / std::max(w, 1e-30);
        worstSkyAll = worstOf(worstSkyAll, relative);
        if (w >= 0.01 * peak) worstSky = worstOf(worstSky, relative);
      }
    }
    std::printf("single scattering, sun %g°, GPU vs double reference: max relative %.3g where at least 1%% of "
                "the channel's peak (%.3g everywhere)\n", elevationDeg, worstSky, worstSkyAll);
    EXPECT_LE(worstSky, 1e-3) << "sun elevation " << elevationDeg;
  }
}

// Multiple scattering (the Ψ_ms table) on the GPU against its CPU twin, texel by texel: the
// sky-view tests turn it off, so nothing else looks at the GPU's table.
TEST(AtmospherePass, MultipleScatteringMatchesItsCpuTwin) {
  gpu::HeadlessContext context;
  AtmosphereParameters p;
  p.multipleScattering = true;
  shared::GpuAtmosphere batch = packAtmosphere(p, glm::vec4(360.0f, 440.0f, 550.0f, 680.0f));
  const AtmosphereTables cpu = computeTables(batch);
  atmosphere::AtmospherePass pass;
  atmosphere::AtmosphereView view;
  view.originKm = float(p.bottomRadiusKm) + 0.2f;
  pass.update({batch}, view);
  const std::vector<glm::vec4> gpuTable = readTexels(pass).multipleScattering[0];
  ASSERT_EQ(gpuTable.size(), cpu.multipleScattering.size());
  ASSERT_FALSE(gpuTable.empty());
  double worst = 0.0;
  for (int j = 0; j < 4; ++j) {
    double peak = 0.0;
    for (const glm::vec4& c : cpu.multipleScattering) peak = std::max(peak, double(c[j]));
    ASSERT_GT(peak, 0.0);
    for (std::size_t i = 0; i < gpuTable.size(); ++i)
      worst = worstOf(worst, std::abs(double(gpuTable[i][j]) - double(cpu.multipleScattering[i][j])) /
                                 std::max(double(cpu.multipleScattering[i][j]), 1e-3 * peak));
  }
  std::printf("multiple scattering, GPU vs CPU twin: max relative %.3g (floored at 1e-3 of each channel's peak)\n", worst);
  EXPECT_LE(worst, 1e-4);
}

// Several batches of one atmosphere, whose transmittance tables are combined from one
// integration of the constituents' densities: each layer is, bit for bit, the table a pass of its
// batch alone makes, and its multiple scattering over it; and both against the CPU twin of that
// batch on the first test's texels, within its bounds.
TEST(AtmospherePass, EveryBatchHasItsOwnTablesFromOneIntegration) {
  gpu::HeadlessContext context;
  AtmosphereParameters p;
  p.multipleScattering = true;
  const std::vector<shared::GpuAtmosphere> batches{packAtmosphere(p, glm::vec4(360.0f, 440.0f, 550.0f, 680.0f)),
                                                   packAtmosphere(p, glm::vec4(600.0f, 620.0f, 700.0f, 830.0f)),
                                                   packAtmosphere(p, glm::vec4(400.0f, 410.0f, 420.0f, 430.0f))};
  atmosphere::AtmospherePass pass;
  atmosphere::AtmosphereView view;
  view.originKm = float(p.bottomRadiusKm) + 0.2f;
  pass.update(batches, view);
  const AtmosphereTexels gpuTables = readTexels(pass);
  ASSERT_EQ(gpuTables.transmittance.size(), batches.size());
  ASSERT_EQ(gpuTables.multipleScattering.size(), batches.size());
  const std::vector<glm::vec4> densities = transmittanceDensities(batches[0]);
  for (std::size_t b = 0; b < batches.size(); ++b) {
    atmosphere::AtmospherePass alone;
    alone.update({batches[b]}, view);
    const AtmosphereTexels own = readTexels(alone);
    EXPECT_EQ(gpuTables.transmittance[b], own.transmittance[0]) << "batch " << b;
    EXPECT_EQ(gpuTables.multipleScattering[b], own.multipleScattering[0]) << "batch " << b;

    const AtmosphereTables cpu = computeTables(batches[b], densities);
    double worstDepth = 0.0, worstMs = 0.0;
    for (int y = 0; y < shared::kTransmittanceLutHeight; y += 3) {
      for (int x = 0; x < shared::kTransmittanceLutWidth; x += 5) {
        const auto i = static_cast<std::size_t>(y * shared::kTransmittanceLutWidth + x);
        for (int j = 0; j < 4; ++j)
          worstDepth = worstOf(worstDepth, std::abs(double(gpuTables.transmittance[b][i][j]) - double(cpu.transmittance[i][j])) /
                                               std::max(double(cpu.transmittance[i][j]), 1e-30));
      }
    }
    for (int j = 0; j < 4; ++j) {
      double peak = 0.0;
      for (const glm::vec4& c : cpu.multipleScattering) peak = std::max(peak, double(c[j]));
      for (std::size_t i = 0; i < cpu.multipleScattering.size(); ++i)
        worstMs = worstOf(worstMs, std::abs(double(gpuTables.multipleScattering[b][i][j]) - double(cpu.multipleScattering[i][j])) /
                                       std::max(double(cpu.multipleScattering[i][j]), 1e-3 * peak));
    }
    std::printf("batch %zu, GPU vs CPU twin: optical depth max relative %.3g, multiple scattering %.3g\n", b,
                worstDepth, worstMs);
    EXPECT_LE(worstDepth, 5e-4) << "batch " << b;
    EXPECT_LE(worstMs, 1e-4) << "batch " << b;
  }
}

// The sky's irradiance coefficients (a compute pass over 192 × 216 cells of the sky-view table's
// own coordinates) against the same projection of the read-back table integrated on the CPU in
// double over 960 × 1080 cells; and the aerial-perspective volume (single scattering only) against the reference
// integrated to each slice's distance.
TEST(AtmospherePass, IrradianceAndAerialPerspectiveMatchIndependentIntegrals) {
  gpu::HeadlessContext context;
  AtmosphereParameters p;
  p.multipleScattering = false;
  shared::GpuAtmosphere batch = packAtmosphere(p, glm::vec4(360.0f, 440.0f, 550.0f, 680.0f));
  const float r = float(p.bottomRadiusKm) + 0.2f;
  const double elevation = 10.0 * kPi / 180.0;
  atmosphere::AtmosphereView view;
  view.originKm = r;
  view.sun = glm::vec3(std::cos(elevation), std::sin(elevation), 0.0f);
  view.inverseViewProjection = glm::mat4(1.0f);  // far points (ndc x, ndc y, 1): a 90° view along +z
  atmosphere::AtmospherePass pass;
  pass.update({batch}, view);

  // Irradiance coefficients.
  AtmosphereTexels texels = readTexels(pass);
  const std::vector<glm::vec4>& sky = texels.skyView[0];
  const std::vector<glm::vec4>& sh = texels.skyIrradiance;
  // Bilinear on texel centres, in double.
  auto at = [&](double u, double v) {
    double fx = u * (shared::kSkyViewLutWidth - 1), fy = v * (shared::kSkyViewLutHeight - 1);
    int x0 = std::min(int(fx), shared::kSkyViewLutWidth - 2), y0 = std::min(int(fy), shared::kSkyViewLutHeight - 2);
    double ax = fx - x0, ay = fy - y0;
    auto texel = [&](int x, int y) { return glm::dvec4(sky[static_cast<std::size_t>(y * shared::kSkyViewLutWidth + x)]); };
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), ax), glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), ax), ay);
  };
  // The table's coordinates (atmosphere_luts.glsl), written again in double.
  const double ch = -std::sqrt((double(r) - p.bottomRadiusKm) * (double(r) + p.bottomRadiusKm)) / r;
  auto cosZenith = [&](double v) {
    return v < 0.5 ? ch + (1.0 - ch) * (1.0 - 2.0 * v) * (1.0 - 2.0 * v) : ch - (1.0 + ch) * (2.0 * v - 1.0) * (2.0 * v - 1.0);
  };
  auto phiOf = [](double u) { return std::acos(std::clamp(1.0 - 2.0 * u * u, -1.0, 1.0)); };
  std::array<glm::dvec4, 4> c{};
  const int nu = 1920, nv = 2160;  // ten times the GPU's cells each way
  for (int iv = 0; iv < nv; ++iv) {
    double v = (iv + 0.5) / nv, dc = cosZenith(double(iv) / nv) - cosZenith(double(iv + 1) / nv);
    double cz = cosZenith(v), sz = std::sqrt(std::max(1.0 - cz * cz, 0.0));
    for (int iu = 0; iu < nu; ++iu) {
      double u = (iu + 0.5) / nu, phi = phiOf(u);
      double dPhi = phiOf(double(iu + 1) / nu) - phiOf(double(iu) / nu);
      glm::dvec4 L = at(u, v) * (dc * dPhi);
      for (double side : {1.0, -1.0}) {  // the sun is along +x here: the table's own frame
        glm::dvec3 d(sz * std::cos(phi), cz, side * sz * std::sin(phi));
        c[0] += L * 0.282095;
        c[1] += L * (0.488603 * d.y);
        c[2] += L * (0.488603 * d.z);
        c[3] += L * (0.488603 * d.x);
      }
    }
  }
  double worstSh = 0.0;
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 4; ++j) {
      worstSh = worstOf(worstSh, std::abs(double(sh[std::size_t(k)][j]) - c[std::size_t(k)][j]) / c[0][j]);
    }
  }
  std::printf("sky irradiance coefficients, GPU vs CPU integral: max error %.3g of the constant term\n", worstSh);
  EXPECT_LE(worstSh, 1e-3);

  // Aerial perspective: columns across the view, slices near and far.
  const std::vector<std::vector<glm::vec4>>& ap = texels.aerialPerspective;
  double worstIn = 0.0, worstT = 0.0;
  for (int y : {8, 16, 24, 31}) {
    for (int x : {0, 16, 31}) {
      glm::dvec3 d = glm::normalize(glm::dvec3(2.0 * x / 31.0 - 1.0, 2.0 * y / 31.0 - 1.0, 1.0));
      double zenith = std::acos(d.y), azimuth = std::atan2(d.z, d.x);
      for (int k : {3, 15, 31}) {
        double distance = double(shared::kAerialPerspectiveMaxKm) * std::pow((k + 1) / 32.0, 2.0);
        ReferenceSegment ref = referenceSingleScatteringTo(p, kLambdas, r, std::sin(elevation), zenith, azimuth, distance);
        glm::vec4 in = ap[std::size_t(k)][std::size_t(y * shared::kAerialPerspectiveSize + x)];
        glm::vec4 t = ap[std::size_t(shared::kAerialPerspectiveSlices + k)][std::size_t(y * shared::kAerialPerspectiveSize + x)];
        for (int j = 0; j < 4; ++j) {
          worstIn = worstOf(worstIn, std::abs(double(in[j]) - ref.radiance[std::size_t(j)]) / ref.radiance[std::size_t(j)]);
          worstT = worstOf(worstT, std::abs(double(t[j]) - ref.transmittance[std::size_t(j)]) / ref.transmittance[std::size_t(j)]);
        }
      }
    }
  }
  std::printf("aerial perspective, GPU vs double reference: in-scattering max relative %.3g, transmittance %.3g\n",
              worstIn, worstT);
  EXPECT_LE(worstIn, 1e-3);
  EXPECT_LE(worstT, 1e-3);
}

}  // namespace
}  // namespace prism::render

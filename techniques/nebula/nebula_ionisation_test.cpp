// Ionisation zones (nebula_ionisation.h): the photon counts against Planck's and Wien's laws
// integrated over wavelength, and the zones of a star in a uniform cloud against the nested
// Strömgren spheres' closed form.
#include "techniques/nebula/nebula_ionisation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/data_files.h"
#include "core/worst_of.h"
#include "techniques/nebula/nebula_light_warnings.h"
#include "techniques/nebula/nebula_precomputed.h"
#include "techniques/nebula/nebula_render.h"
#include "techniques/nebula/nebula_scene.h"

namespace prism::nebula {
namespace {

// Photons above E per unit of band luminosity, from Planck's B_λ (any units) by composite Simpson
// in λ: the photons ∫₀^λ_E B_λ·λ dλ (fine steps: the Wien tail is steep) over ∫ B_λ dλ on the band.
double photonsByQuadrature(double energyEv, double temperatureK, StarModel model = StarModel::Planck) {
  constexpr double hcEvUm = 1.239841984, kEvPerK = 8.617333262e-5;
  auto planck = [&](double lambdaUm) {
    const double x = hcEvUm / (lambdaUm * kEvPerK * temperatureK);
    return 1.0 / (std::pow(lambdaUm, 5) * (model == StarModel::Wien ? std::exp(x) : std::expm1(x)));
  };
  auto simpson = [](auto f, double a, double b, int n) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
    return sum * h / 3.0;
  };
  const double edge = hcEvUm / energyEv;
  const double photons = simpson([&](double l) { return l > 0.0 ? planck(l) * l : 0.0; }, 1e-4, edge, 200000);
  return photons / simpson(planck, kBandLoUm, kBandHiUm, 2000);
}

TEST(NebulaIonisation, PhotonCountsArePlancksLaw) {
  const double reference = photonsByQuadrature(kHydrogenIonisationEv, 40000.0);
  EXPECT_NEAR(ionisingPhotons(kHydrogenIonisationEv, 40000.0), 1.0, 1e-12);
  for (double t : {10000.0, 25000.0, 40000.0, 80000.0})
    for (double e : {13.598434, 24.587389, 35.12112, 54.93554}) {
      for (StarModel model : {StarModel::Planck, StarModel::Wien}) {
        const double expected = photonsByQuadrature(e, t, model) / reference;
        EXPECT_NEAR(ionisingPhotons(e, t, model), expected, 1e-6 * expected)
            << e << " eV at " << t << " K, " << (model == StarModel::Wien ? "Wien" : "Planck");
      }
    }
  // Hotter stars make more ionising photons for their visible light, and more energetic ones.
  EXPECT_LT(ionisingPhotons(kHydrogenIonisationEv, 25000.0), ionisingPhotons(kHydrogenIonisationEv, 40000.0));
  EXPECT_LT(ionisingPhotons(35.12112, 40000.0), ionisingPhotons(24.587389, 40000.0));
}

// One star of luminosity 1 in a cloud of density 1 filling the cube: every ion's zone is a
// shell between the Strömgren radii R₀·q(E)^⅓ of the energies that make and destroy it (C = r³/3).
// Bound per voxel: the column's midpoint rule over ∫₀ʳ s² ds in n = ⌈r/h⌉ steps (h = 1/64) is off
// by 1/(4n²) relative, the radius ratio u = C^⅓ by 1/(12n²); each of a zone's two fronts turns
// that into at most 1.5/(2w)·(1 + w)·u·1/(12n²), so the bound is twice that (w = 0.05), plus
// float's storage.
TEST(NebulaIonisation, AStarInAUniformCloudHasNestedStromgrenZones) {
  NebulaModel m;
  m.density = {32, 32, 32, std::vector<float>(32 * 32 * 32, 1.0f)};
  const IonisationModel zones{0.3, 0.05};
  const std::vector<std::string> groups = {"H I Balmer (case B)", "[O III] doublet", "[S II] doublet", "[O I] doublet"};
  const std::vector<IonZone> table = readIonZones(dataFile("nebula_ions.csv"));
  for (double t : {40000.0, 25000.0}) {
    const NebulaStar star{{0.5, 0.5, 0.5}, t, 1.0};
    const VoxelField field =
        ionisationZones(m.density, {star}, StarModel::Planck, {recombinationColumn(m.density, star, 0)}, zones, groups, 0);
    auto analytic = [&](const std::string& group, double r) {
      auto f = [&](double e) { return 1.0 - glm::smoothstep(0.95, 1.05, r / (0.3 * std::cbrt(ionisingPhotons(e, t)))); };
      for (const IonZone& z : table)
        if (z.group == group)
          return f(std::max(z.makeEv, kHydrogenIonisationEv)) * (std::isfinite(z.destroyEv) ? 1.0 - f(z.destroyEv) : 1.0);
      return std::numeric_limits<double>::quiet_NaN();
    };
    double worst = 0.0, worstRatio = 0.0, oiiiPeak = 0.0;
    for (int k = 0; k < 32; ++k)
      for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 32; ++i) {
          const double r = glm::length(glm::dvec3((i + 0.5) / 32, (j + 0.5) / 32, (k + 0.5) / 32) - star.position);
          const std::size_t v = (static_cast<std::size_t>(k) * 32 + static_cast<std::size_t>(j)) * 32 + static_cast<std::size_t>(i);
          const double n = std::ceil(r * 64.0);
          const double bound = 2.0 * 1.5 / (2.0 * 0.05) * 1.05 / (12.0 * n * n) + 1e-6;
          for (std::size_t g = 0; g < groups.size(); ++g) {
            const double e = std::abs(field.values[v * groups.size() + g] - analytic(groups[g], r));
            worst = worstOf(worst, e);
            worstRatio = worstOf(worstRatio, e / bound);
          }
          oiiiPeak = std::max(oiiiPeak, static_cast<double>(field.values[v * groups.size() + 1]));
        }
    std::printf("%.0f K: zones against the nested Strömgren spheres, max difference %.2e (%.2f of the bound); "
                "[O III] at most %.3g; hydrogen's front at r = %.3f, O++'s at %.3f\n",
                t, worst, worstRatio, oiiiPeak, 0.3 * std::cbrt(ionisingPhotons(kHydrogenIonisationEv, t)),
                0.3 * std::cbrt(ionisingPhotons(35.12112, t)));
    EXPECT_LE(worstRatio, 1.0) << t;
    if (t == 40000.0) EXPECT_GT(oiiiPeak, 0.99);  // an O star's core glows in [O III]
    else EXPECT_LT(oiiiPeak, 1e-3);               // a B star's makes no O++
  }
}

// A renderer with zones draws its lines only where they glow: an O star's hydrogen zone, smaller
// than the cloud, holds part of its Balmer light; a B star makes no O++, so its [O III] vanishes.
TEST(NebulaIonisation, ZonesDimTheLinesOutsideThem) {
  auto light = [](const std::string& group, double temperatureK, bool zoned) {
    NebulaModel m = benchNebulaModel(0);
    m.emission = 0.01;
    m.scattering = 0.0;  // the lines alone
    m.lineGroups = {{group, 1.0}};
    m.stars = {{{0.5, 0.5, 0.5}, temperatureK, 1.0}};
    m.filters = "cie1931";
    m.camera.width = m.camera.height = 16;
    if (zoned) m.ionisation = IonisationModel{0.15, 0.1};
    RenderSettings s;
    s.method = Method::Projection;
    s.threads = 0;
    double y = 0.0;
    for (const glm::vec3& p : NebulaRenderer(m, s).render(s).pixels) y += p.y;
    return y;
  };
  const double balmer = light("H I Balmer (case B)", 40000.0, false), balmerZoned = light("H I Balmer (case B)", 40000.0, true);
  const double oiii = light("[O III] doublet", 25000.0, false), oiiiZoned = light("[O III] doublet", 25000.0, true);
  std::printf("Balmer light in a 40 000 K star's zones: %.3f of the unzoned; [O III] in a 25 000 K star's: %.2g\n",
              balmerZoned / balmer, oiiiZoned / oiii);
  EXPECT_GT(balmerZoned, 0.05 * balmer);
  EXPECT_LT(balmerZoned, 0.7 * balmer);
  EXPECT_LT(oiiiZoned, 1e-3 * oiii);
}

// Zones with no star to make them: the lines glow nowhere, and the model says so (the image was
// black without a word). Not so without zones, without lines, or with a star that shines.
TEST(NebulaIonisation, ZonesWithoutAShiningStarWarnThatNoLineGlows) {
  NebulaModel m = benchNebulaModel(0);
  m.emission = 0.01;
  m.lineGroups = {{"H I Balmer (case B)", 1.0}};
  EXPECT_EQ(unlitLinesWarning(m), "");
  m.ionisation = IonisationModel{};
  EXPECT_NE(unlitLinesWarning(m).find("no emission line glows"), std::string::npos);
  m.stars = {{{0.5, 0.5, 0.5}, 40000.0, 0.0}};
  EXPECT_NE(unlitLinesWarning(m), "") << "a star of luminosity 0 ionises nothing";
  m.camera.width = m.camera.height = 8;
  RenderSettings s;
  s.method = Method::Projection;
  double y = 0.0;
  for (const glm::vec3& p : NebulaRenderer(m, s).render(s).pixels) y += p.y;
  EXPECT_EQ(y, 0.0) << "what the warning says";
  m.stars[0].luminosity = 1.0;
  EXPECT_EQ(unlitLinesWarning(m), "");
  m.stars.clear();
  m.lineGroups = {{"H I Balmer (case B)", 0.0}};
  EXPECT_EQ(unlitLinesWarning(m), "") << "no line asked for";
  m.lineGroups = {{"H I Balmer (case B)", 1.0}};
  m.emission = 0.0;
  EXPECT_EQ(unlitLinesWarning(m), "") << "no emission";
}

// A nebula that gives no light at all (a new-user review rendered each of these black, with no
// word): nothing to scatter and nothing that glows within the filters, each cause named; not said
// where unlitLinesWarning speaks, nor where anything gives light.
TEST(NebulaIonisation, ANebulaThatGivesNoLightIsSaid) {
  const RenderSettings s;
  auto warning = [&s](NebulaModel m) {
    m.camera.width = m.camera.height = 4;
    NoiseParameters small;
    small.resolution = 16;
    m.density = generateFbm(small, 1);
    const NebulaRenderer renderer(std::move(m), s);
    return darkNebulaWarning(renderer);
  };
  NebulaModel m = benchNebulaModel(1);
  m.emission = 0.0;
  EXPECT_EQ(warning(m), "");
  const std::string black = "the nebula gives no light, it only dims what lies behind it (its own image is black): ";
  m.stars[0].luminosity = 0.0;
  EXPECT_EQ(warning(m), black + "no star of luminosity above 0 to scatter the light of, and emission 0");
  m.stars[0].luminosity = 1.0;
  m.scattering = 0.0;
  m.emission = 0.01;
  m.lineGroups = {{"H I Balmer (case B)", 0.0}};
  EXPECT_EQ(warning(m), black + "scattering 0, which scatters no star's light, and no emission line of strength above 0");
  m.stars.clear();
  m.filters = "cie1931";
  m.lineGroups = {{"[O II] doublet", 1.0}};  // 372.6 and 372.9 nm, where no CIE 1931 curve is fitted
  EXPECT_EQ(warning(m), black + "no star to scatter the light of, and emission lines only outside every passband of the "
                                "cie1931 filters");
  m.lineGroups = {{"H I Balmer (case B)", 1.0}};
  EXPECT_EQ(warning(m), "") << "the Balmer lines glow within the CIE curves";
  m.lineGroups = {{"[O II] doublet", 1.0}};
  m.ionisation = IonisationModel{};
  EXPECT_EQ(warning(m), "") << "unlitLinesWarning says it";
}

}  // namespace
}  // namespace prism::nebula

// The methods against the reference on a small nebula (24³ density, 32×32 pixels, so that the
// test runs in seconds): the paper's claim, projection on 4 elements within 2 % of the reference
// per pixel, and what each other method measures. Emission lines are off here (every method adds
// them the same exact way, which would only dilute the differences).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "techniques/nebula/nebula_precomputed.h"
#include "techniques/nebula/nebula_render.h"
#include "techniques/nebula/nebula_test_cloud.h"

namespace prism::nebula {
namespace {

// The small cloud, its stars moved three times as far from the cube's middle when `distant`.
NebulaModel smallNebula(std::string filters, int starCount, bool distant = false) {
  NebulaModel m = smallCloud(std::move(filters), starCount);
  if (distant)
    for (auto& st : m.stars) st.position = glm::dvec3(0.5) + 3.0 * (st.position - glm::dvec3(0.5, 0.5, 0.4));
  return m;
}

struct Errors {
  double preIntegration, analytic, projection, projectionClosedForm, lightDensity, lightDensityTotal, referenceConvergence;
  double analyticBound;
};

// The analytic method's one approximation is each star's spectrum (scattered through P_σ) as its
// fit P_L: a pixel sums the stars' light, so it stays within the worst star's fit error (≤ 1e-4
// over 1 000–100 000 K, NebulaSpectra.StarFitAndNormalisation), plus 1e-5 for float's rounding and
// the reference's own convergence.
double analyticBound(const NebulaModel& m) {
  double worst = 0.0;
  for (const NebulaStar& star : m.stars)
    worst = std::max(worst, makeStarSpectrum(star.temperatureK, m.starModel, m.scatteringSpectrum).fitMaxRelativeError);
  return worst + 1e-5;
}

Errors measure(const std::string& filters, int stars, bool doublePrecision = false, bool distant = false,
               const std::array<PassbandEdit, 3>& passbands = {}) {
  RenderSettings s;
  s.doublePrecision = doublePrecision;
  s.emissionLines = false;
  NebulaModel model = smallNebula(filters, stars, distant);
  model.passbands = passbands;
  const double bound = analyticBound(model);
  NebulaRenderer r(std::move(model), s);
  s.method = Method::Reference;
  NebulaImage reference = r.render(s);
  s.referenceIntervals = 32;
  NebulaImage finer = r.render(s);
  double peak = 0.0;  // a black reference would hold every method to nothing
  for (const auto& p : finer.pixels) peak = std::max({peak, double(p.x), double(p.y), double(p.z)});
  EXPECT_GT(peak, 0.0) << filters;
  Errors e{};
  e.analyticBound = bound;
  e.referenceConvergence = maxRelativeError(reference, finer);
  s.method = Method::Analytic;
  e.analytic = maxRelativeError(r.render(s), finer);
  s.method = Method::PreIntegration;
  e.preIntegration = maxRelativeError(r.render(s), finer);
  s.method = Method::Projection;
  e.projection = maxRelativeError(r.render(s), finer);
  s.momentTable = false;
  e.projectionClosedForm = maxRelativeError(r.render(s), finer);
  s.momentTable = true;
  s.method = Method::LightDensity;
  NebulaImage ld = r.render(s);
  e.lightDensity = maxRelativeError(ld, finer);
  for (int c = 0; c < 3; ++c) {  // the image's total per channel
    double a = 0, b = 0;
    for (std::size_t i = 0; i < ld.pixels.size(); ++i) a += ld.pixels[i][c], b += finer.pixels[i][c];
    e.lightDensityTotal = std::max(e.lightDensityTotal, std::abs(a / b - 1.0));
  }
  std::printf("%s%s, %d %sstar(s): max relative error per pixel vs reference: analytic %.3g, projection(4) %.3g (closed form per sample %.3g), "
              "light-density(8) %.3g (image total %.2g), pre-integration %.3g; reference 16 vs 32 intervals %.2g\n",
              doublePrecision ? "double " : "float ", filters.c_str(), stars, distant ? "distant " : "", e.analytic, e.projection, e.projectionClosedForm, e.lightDensity, e.lightDensityTotal,
              e.preIntegration, e.referenceConvergence);
  return e;
}

// The measure every method is held by: a non-finite pixel is infinitely wrong, and against a
// black reference, where no pixel is compared, it is NaN rather than a perfect 0.
TEST(NebulaRender, TheRelativeErrorOfANonFinitePixelIsInfinite) {
  const NebulaImage reference{2, 1, {glm::vec3(1.0f), glm::vec3(0.0f)}};
  EXPECT_NEAR(maxRelativeError({2, 1, {glm::vec3(1.5f), glm::vec3(0.0f)}}, reference), 0.5, 1e-12);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // Also where the reference is black, which the measure otherwise leaves out.
  for (const glm::vec3 bad : {glm::vec3(nan, 1.0f, 1.0f), glm::vec3(0.0f, inf, 0.0f)}) {
    EXPECT_EQ(maxRelativeError({2, 1, {glm::vec3(1.0f), bad}}, reference), std::numeric_limits<double>::infinity());
    EXPECT_EQ(maxRelativeError({2, 1, {bad, glm::vec3(0.0f)}}, reference), std::numeric_limits<double>::infinity());
  }
  const NebulaImage black{2, 1, {glm::vec3(0.0f), glm::vec3(0.0f)}};
  EXPECT_TRUE(std::isnan(maxRelativeError(reference, black)));
  EXPECT_EQ(maxRelativeError({2, 1, {glm::vec3(nan), glm::vec3(0.0f)}}, black), std::numeric_limits<double>::infinity());
}

TEST(NebulaRender, TheCoefficientTableHoldsFromTheFirstInterval) {
  RenderSettings s;
  NebulaRenderer r(smallNebula("cie1931", 1), s);
  const NebulaPrecomputed& pre = r.precomputed();
  const int card = static_cast<int>(pre.basis.a.size());
  double worstFirst = 0.0, worstLater = 0.0;
  for (double steps : {0.1, 1.0 / 3.0, 0.5, 0.9, 1.5, 7.25, 100.5, 2000.3}) {
    const double x = steps * pre.moments.step;
    std::array<double, 8> raw{}, exact{};
    glm::dvec4 lo = shared::f64::nebulaExpMoments(x, pre.exponents(0), kBandLoUm, kBandHiUm);
    glm::dvec4 hi = shared::f64::nebulaExpMoments(x, pre.exponents(1), kBandLoUm, kBandHiUm);
    for (int j = 0; j < 4; ++j) raw[static_cast<std::size_t>(j)] = lo[j], raw[static_cast<std::size_t>(j + 4)] = hi[j];
    pre.toCoefficients(raw, exact);
    glm::vec4 tLo(0.0f), tHi(0.0f);
    ASSERT_TRUE(pre.moments.lookup(x, tLo, tHi, card > 4));
    double scale = 0.0, error = 0.0;
    for (int k = 0; k < card; ++k) {
      const double table = k < 4 ? tLo[k] : tHi[k - 4];
      scale = std::max(scale, std::abs(exact[static_cast<std::size_t>(k)]));
      error = std::max(error, std::abs(table - exact[static_cast<std::size_t>(k)]));
    }
    (steps < 1.0 ? worstFirst : worstLater) = std::max(steps < 1.0 ? worstFirst : worstLater, error / scale);
  }
  std::printf("coefficient table against double, relative to the largest: first interval %.3g, later %.3g\n",
              worstFirst, worstLater);
  EXPECT_LE(worstFirst, 1e-6);
  EXPECT_LE(worstLater, 1e-6);
}

// The paper's claim, in float (the GPU's precision). The double run shows how much of the
// error is float's: the raw moments' rounding amplified by the basis's matrix M.
TEST(NebulaRender, ProjectionWithFourElementsIsWithinTwoPercentOfTheReference) {
  for (const char* filters : {"hubble", "cie1931"}) {
    Errors d = measure(filters, 1, true);
    Errors e = measure(filters, 1);
    EXPECT_LT(e.referenceConvergence, 1e-4);  // the reference is converged in λ
    EXPECT_LE(e.projection, 0.02);
    EXPECT_LE(e.projectionClosedForm, 0.02);
    EXPECT_LE(d.projection, e.projection);
    // The analytic method, in both precisions, over the CIE curves' broad pieces and the HST
    // bands' narrow ones (the series there, nebula_integrals.glsl): the P_L fit's error and no
    // more (measured 8.9e-6 and 5.1e-6; the closed form alone was 85× off on Hubble in double,
    // 10 800× in float).
    EXPECT_LE(d.analytic, d.analyticBound);
    EXPECT_LE(e.analytic, e.analyticBound);
  }
}

// Passbands moved and resized (the viewer's filter controls) stay polynomials of their degree,
// so every method integrates them as it did the fitted ones: projection within the 2 %.
TEST(NebulaRender, EditedPassbandsKeepProjectionWithinTwoPercent) {
  Errors e = measure("hubble", 1, false, false, {PassbandEdit{15.0, 1.5}, PassbandEdit{-10.0, 3.0}, PassbandEdit{30.0, 0.5}});
  EXPECT_LT(e.referenceConvergence, 1e-4);
  EXPECT_LE(e.projection, 0.02);
  EXPECT_LE(e.preIntegration, 1e-6);  // as for the fitted passbands (ThreeStarsOfDifferentColours)
  EXPECT_LE(e.analytic, e.analyticBound);
}

// Refiltering (the viewer's passband edits) copies the volume and makes again what the filters
// change: every method renders what a renderer built from the edited model renders, bit for bit.
TEST(NebulaRender, RefilteringIsAFreshRendererBitForBit) {
  RenderSettings s;
  NebulaModel model = smallNebula("hubble", 2);
  model.lineGroups = {{"H I Balmer (case B)", 1.0}, {"[O III] doublet", 0.5}};
  model.emission = 0.01;
  model.ionisation = IonisationModel{0.4, 0.1};  // the zones are the volume's: copied
  NebulaRenderer volume(model, s);
  const std::array<PassbandEdit, 3> edits{PassbandEdit{20.0, 2.0}, PassbandEdit{}, PassbandEdit{-15.0, 0.5}};
  const auto start = std::chrono::steady_clock::now();
  NebulaRenderer refiltered(volume, "cie1931", edits);
  const double refilterS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  model.filters = "cie1931";
  model.passbands = edits;
  const auto freshStart = std::chrono::steady_clock::now();
  NebulaRenderer fresh(model, s);
  const double freshS = std::chrono::duration<double>(std::chrono::steady_clock::now() - freshStart).count();
  std::printf("refiltered in %.1f ms, built afresh in %.1f ms\n", 1e3 * refilterS, 1e3 * freshS);
  for (Method method : {Method::Reference, Method::Analytic, Method::Projection, Method::LightDensity, Method::PreIntegration}) {
    s.method = method;
    EXPECT_EQ(refiltered.render(s).pixels, fresh.render(s).pixels) << methodName(method);
  }
  EXPECT_EQ(refiltered.model().filters, "cie1931");
  EXPECT_EQ(refiltered.model().passbands, edits);
}

TEST(NebulaRender, ThreeStarsOfDifferentColours) {
  Errors e = measure("cie1931", 3);
  EXPECT_LE(e.projection, 0.02);
  // Pre-integration is the reference's own integral tabulated over x (4096 entries, Catmull–Rom
  // in float): within float's rounding, 1e-6 (measured 1.2e-7; 1.7e-4 while the entry before 0
  // mirrored the one after, flattening the table's first interval near the stars).
  EXPECT_LE(e.preIntegration, 1e-6);
  // The analytic method: through P_L's fit, in float.
  EXPECT_LE(e.analytic, e.analyticBound);
  // The light–density method is not held to the paper's 2 % here: with stars inside the cloud it
  // stores σ₁L/(16π²d²) per voxel and interpolates it across voxels next to the star, which the
  // others evaluate exactly per sample. Held instead as a regression guard at the README's
  // figures with a fifth to spare (measured: 30 % per pixel, 1.9 % on the image's total at 24³).
  EXPECT_LE(e.lightDensity, 0.36);
  EXPECT_LE(e.lightDensityTotal, 0.023);
}

}  // namespace
}  // namespace prism::nebula

namespace prism::nebula {
namespace {
TEST(NebulaRender, DistantStars) {
  Errors e = measure("cie1931", 3, false, true);
  EXPECT_LE(e.projection, 0.02);
  // Stars outside the cloud: the light–density method's per-voxel light is smooth, and only its
  // linear interpolation of the projected light (the others interpolate g_s, then exponentiate)
  // separates it from the reference: within 1 % on the image's total (measured 0.75 %).
  EXPECT_LE(e.lightDensityTotal, 0.01);
  // Per pixel, a regression guard at the README's figure with a fifth to spare (measured 4.9 %).
  EXPECT_LE(e.lightDensity, 0.059);
  EXPECT_LE(e.analytic, e.analyticBound);  // through P_L's fit, in float
}
}  // namespace
}  // namespace prism::nebula

namespace prism::nebula {
namespace {

// The projection's error against the basis size (the paper's plot, as a table): it must fall
// tenfold with every element, in double and in float. The fifth does (3.6e-6) only with raw
// moments as exact as the orthonormalisation they meet: with the exponents' float roundings its
// ill-conditioned row made it 1.2 %; with the exponential integrals' continued fraction cut at
// depth 24 in double (6e-8), 0.053 %.
TEST(NebulaRender, ProjectionErrorFallsWithTheBasisSize) {
  RenderSettings s;
  s.emissionLines = false;
  s.doublePrecision = true;
  NebulaModel model = smallNebula("cie1931", 1);
  double previous = 1e30;
  NebulaImage reference;
  for (int size = 1; size <= 5; ++size) {
    s.basisSize = size;
    NebulaRenderer r(model, s);
    if (size == 1) {
      s.method = Method::Reference;
      reference = r.render(s);
    }
    s.method = Method::Projection;
    double d = maxRelativeError(r.render(s), reference);
    s.doublePrecision = false;
    double f = maxRelativeError(r.render(s), reference);
    s.doublePrecision = true;
    std::printf("basis size %d: max relative error per pixel, double %.3g, float %.3g\n", size, d, f);
    EXPECT_LT(d, previous / 10.0);
    EXPECT_LT(f, previous / 10.0);
    previous = d;
  }
}

}  // namespace
}  // namespace prism::nebula

namespace prism::nebula {
namespace {

// A camera looking straight up or down (before: +y gave no right, the rays were NaN and the
// marcher read outside the grid and crashed): the cloud's light is what a camera a hair off the
// vertical sees — the same square image turned a quarter.
TEST(NebulaRender, ACameraLookingStraightUpOrDownSeesTheCloud) {
  RenderSettings s;
  s.method = Method::Projection;
  s.steps = 60;
  const auto total = [](const NebulaImage& image) {
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : image.pixels) sum += glm::dvec3(p);
    return sum;
  };
  for (double y : {-1.0, 2.0}) {
    NebulaModel vertical = smallNebula("cie1931", 2);
    vertical.camera.position = {0.5, y, 0.5};
    NebulaModel tilted = vertical;
    tilted.camera.position.x += 1e-6;
    const glm::dvec3 straight = total(NebulaRenderer(vertical, s).render(s));
    const glm::dvec3 aside = total(NebulaRenderer(tilted, s).render(s));
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(straight[c], 0.0) << "camera at y " << y;
      EXPECT_NEAR(straight[c], aside[c], 1e-3 * aside[c]) << "camera at y " << y << ", channel " << c;
    }
  }
}

// A Wien star needs no fit: the analytic method integrates its λ⁻⁵e^(−B/λ) against each passband
// piece exactly (negative powers of λ), so it meets the converged reference to the quadrature's
// own digits, where a Planck star's two quintic pieces leave their fit's error.
TEST(NebulaRender, TheAnalyticMethodIntegratesAWienStarExactly) {
  for (const char* filters : {"cie1931", "hubble"}) {
    NebulaModel model = smallNebula(filters, 3);
    RenderSettings s;
    s.emissionLines = false;
    s.doublePrecision = true;
    double error[2] = {};
    for (StarModel starModel : {StarModel::Wien, StarModel::Planck}) {
      model.starModel = starModel;
      NebulaRenderer r(model, s);
      s.method = Method::Reference;
      s.referenceIntervals = 64;
      NebulaImage reference = r.render(s);
      s.method = Method::Analytic;
      error[starModel == StarModel::Planck] = maxRelativeError(r.render(s), reference);
    }
    s.doublePrecision = false;
    model.starModel = StarModel::Wien;
    NebulaRenderer r(model, s);
    s.method = Method::Reference;
    NebulaImage reference = r.render(s);
    s.method = Method::Analytic;
    const double wienFloat = maxRelativeError(r.render(s), reference);
    std::printf("%s, 3 stars, analytic against the reference (64 intervals): Wien exact %.3g (float %.3g), Planck "
                "through its fit %.3g\n",
                filters, error[0], wienFloat, error[1]);
    // Exact but for rounding, on the CIE curves' broad pieces and the HST bands' 0.3–1 nm ones
    // alike (the series there; the closed form in powers of λ alone was 4.2e-7 off in double and
    // 149× in float on Hubble), in float too.
    EXPECT_LE(error[0], 1e-6);
    EXPECT_LT(error[0] * 20.0, error[1]);
    EXPECT_LE(wienFloat, 1e-6);
  }
}

}  // namespace
}  // namespace prism::nebula

namespace prism::nebula {
namespace {

// Dust whose scattering follows its extinction (P_σ = CCM's quadratic): every method carries P_σ
// in the stars' scattered spectra, so they keep their accuracy against the reference, and the
// scattered light turns bluer (reflection nebulae are blue). A Wien star under a linear P_σ stays
// exact in the analytic method (P_S·P_σ cubic).
TEST(NebulaRender, DustScatteringWithASpectrum) {
  NebulaModel grey = smallNebula("cie1931", 3);
  NebulaModel dusty = grey;
  dusty.scatteringSpectrum = ccmScattering();
  RenderSettings s;
  s.emissionLines = false;
  NebulaRenderer greyRenderer(grey, s), dustyRenderer(dusty, s);
  s.method = Method::Reference;
  const NebulaImage greyImage = greyRenderer.render(s), reference = dustyRenderer.render(s);
  s.method = Method::Projection;
  const double projection = maxRelativeError(dustyRenderer.render(s), reference);
  s.method = Method::PreIntegration;
  const double preIntegration = maxRelativeError(dustyRenderer.render(s), reference);
  s.method = Method::Analytic;
  const double analytic = maxRelativeError(dustyRenderer.render(s), reference);
  s.doublePrecision = true;
  const double analyticDouble = maxRelativeError(dustyRenderer.render(s), reference);
  s.doublePrecision = false;
  glm::dvec3 greySum(0.0), dustySum(0.0);
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) greySum += glm::dvec3(greyImage.pixels[i]), dustySum += glm::dvec3(reference.pixels[i]);
  const double greyBlue = greySum.z / greySum.y, dustyBlue = dustySum.z / dustySum.y;  // z̄ against ȳ
  NebulaModel wien = dusty;
  wien.starModel = StarModel::Wien;
  wien.scatteringSpectrum = greyScattering();
  wien.scatteringSpectrum.coeffs[0] = 2.2;  // 2.2 − 1.6λ: CCM's slope, linear
  wien.scatteringSpectrum.coeffs[1] = -1.6;
  s.doublePrecision = true;
  NebulaRenderer wienRenderer(wien, s);
  s.method = Method::Reference;
  s.referenceIntervals = 64;
  const NebulaImage wienReference = wienRenderer.render(s);
  s.method = Method::Analytic;
  const double wienAnalytic = maxRelativeError(wienRenderer.render(s), wienReference);
  std::printf("P_σ = CCM, 3 stars: projection %.3g, pre-integration %.3g, analytic %.3g (double %.3g) against the "
              "reference; Z/Y of the image %.3f (grey dust %.3f); Wien under a linear P_σ, analytic in double %.3g\n",
              projection, preIntegration, analytic, analyticDouble, dustyBlue, greyBlue, wienAnalytic);
  EXPECT_LE(projection, 0.02);
  EXPECT_LE(preIntegration, 1e-6);
  // The analytic method goes through the fit of S·P_σ (two quintic pieces, 7.7e-4 of the
  // 25 000 K star's scattered spectrum at most): within it, in float and in double (measured 1.0e-5).
  EXPECT_LE(analytic, analyticBound(dusty));
  EXPECT_LE(analyticDouble, analyticBound(dusty));
  EXPECT_GT(dustyBlue, greyBlue * 1.1);
  EXPECT_LE(wienAnalytic, 1e-6);
}

}  // namespace
}  // namespace prism::nebula

// The nebula's inputs and its bases: fits, Planck against published values, the density file
// format's errors, the noise's determinism, the greedy basis on the paper's domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/data_files.h"
#include "core/error_test_support.h"
#include "core/temp_file_test_support.h"
#include "core/worst_of.h"
#include "techniques/nebula/nebula_basis.h"
#include "techniques/nebula/nebula_density.h"
#include "techniques/nebula/nebula_integrals.h"
#include "techniques/nebula/nebula_spectra.h"

namespace prism::nebula {
namespace {

TEST(NebulaSpectra, PolynomialFitReproducesAPolynomialExactly) {
  std::vector<double> l, v;
  for (int i = 0; i <= 50; ++i) {
    l.push_back(0.4 + 0.3 * i / 50.0);
    v.push_back(1.0 - 2.0 * l.back() + 3.0 * l.back() * l.back());
  }
  PiecewisePolynomial p = fitPiecewisePolynomial(l, v, 0.4, 0.7, 3, 2);
  for (std::size_t i = 0; i < l.size(); ++i) EXPECT_NEAR(p.at(l[i]), v[i], 1e-10);
  EXPECT_EQ(p.at(0.39), 0.0);
}

TEST(NebulaSpectra, PlanckPeaksWhereWienSays) {
  // Wien's displacement law, λ_max·T = 2897.77 µm·K (CODATA 2018).
  double best = 0, bestL = 0;
  for (double l = 0.2; l < 1.2; l += 1e-5)
    if (planck(l, 5800.0) > best) best = planck(l, 5800.0), bestL = l;
  EXPECT_NEAR(bestL * 5800.0, 2897.77, 0.1);
  // Wien's approximation is within e^(−hc/λkT) of Planck: 0.0137 % at 500 nm, 5800 K.
  EXPECT_NEAR(wien(0.5, 5800.0) / planck(0.5, 5800.0), 1.0 - std::exp(-14387.768775 / (0.5 * 5800.0)), 1e-12);
}

TEST(NebulaSpectra, CcmExtinctionIsNormalisedAtVAndKeepsItsRv) {
  // A(V)/A(V) = 1 (y = 0 leaves a = 1, b = 0), and R_V = A(V)/E(B − V) makes A(B)/A(V) = 1 + 1/R_V,
  // which CCM's fit keeps within its own accuracy, for the diffuse medium and dense clouds alike.
  EXPECT_NEAR(ccmExtinction(1.0 / 1.82), 1.0, 1e-12);
  for (double rv : {3.1, 5.0}) EXPECT_NEAR(ccmExtinction(0.44, rv), 1.0 + 1.0 / rv, 0.01 * (1.0 + 1.0 / rv)) << rv;
  // The infrared and optical pieces meet at 1/λ = 1.1 µm⁻¹ (to the fit's percent).
  EXPECT_NEAR(ccmExtinction(1.0 / 1.0999) / ccmExtinction(1.0 / 1.1001), 1.0, 0.02);
  EXPECT_THROW(ccmExtinction(0.25), Error);  // 1/λ = 4: the ultraviolet, beyond Eq. 3
  EXPECT_THROW(ccmExtinction(0.5, 0.0), Error);
  // The model's C_T/λ against it over the visible band (printed; the README's table).
  double worst = 0.0, worstAt = 0.0;
  for (double l = kBandLoUm; l <= kBandHiUm + 1e-9; l += 0.005) {
    const double d = modelExtinction(l) / ccmExtinction(l) - 1.0;
    if (std::abs(d) > std::abs(worst)) worst = d, worstAt = l;
  }
  std::printf("C_T/λ against CCM (R_V = 3.1) over 0.38–0.78 µm: worst %+.2f %% at %.3f µm\n", 100.0 * worst, worstAt);
  // Measured +12.5 % at 0.78 µm (−6.3 % at 0.42): the 1/λ law is CCM's optical slope to about a
  // tenth; a law of another power (1/λ² is off by half at the band's ends) is not.
  EXPECT_LT(std::abs(worst), 0.15);
}

TEST(NebulaSpectra, CcmScatteringIsACubicThroughTheMeasuredCurve) {
  // P_σ for dust of constant albedo follows its extinction: the cubic fit of CCM over the band.
  const PolynomialPiece p = ccmScattering();
  EXPECT_EQ(degree(p), 3);
  double worst = 0.0;
  for (int i = 0; i <= 80; ++i) {
    const double l = kBandLoUm + (kBandHiUm - kBandLoUm) * i / 80.0;
    worst = worstOf(worst, std::abs(p.at(l) / ccmExtinction(l) - 1.0));
  }
  std::printf("CCM's cubic fit over the band: worst %.2g relative\n", worst);
  // A cubic in λ bends less than CCM's optical polynomial in 1/λ (its knee near 0.45 µm): 2.0 %
  // measured (a quadratic: 5.0 %), a sixth of how far the model's own C_T/λ is from CCM.
  EXPECT_LT(worst, 0.025);
  // A star's scattered spectrum carries it; its normalisation is the star's alone.
  StarSpectrum grey = makeStarSpectrum(8000.0, StarModel::Planck);
  StarSpectrum dusty = makeStarSpectrum(8000.0, StarModel::Planck, p);
  EXPECT_DOUBLE_EQ(dusty.normalisation, grey.normalisation);
  EXPECT_NEAR(dusty.at(0.45) / grey.at(0.45), p.at(0.45), 1e-12 * p.at(0.45));
  EXPECT_LT(dusty.fitMaxRelativeError, 1e-3);
}

TEST(NebulaSpectra, StarFitAndNormalisation) {
  // 42 000 K: ionised.json's hottest; 1 000 K, the coolest a scene takes.
  for (double t : {1000.0, 1250.0, 3000.0, 5800.0, 10000.0, 30000.0, 42000.0, 50000.0, 100000.0}) {
    StarSpectrum s = makeStarSpectrum(t, StarModel::Planck);
    std::printf("star %.0f K: P_L (degree 5) max relative error %.2e, %zu pieces\n", t, s.fitMaxRelativeError,
                s.fit.pieces.size());
    EXPECT_LE(s.fitMaxRelativeError, 1e-4);
    double sum = 0;
    for (int i = 0; i < 4000; ++i) sum += s.at(kBandLoUm + (kBandHiUm - kBandLoUm) * (i + 0.5) / 4000) * 1e-4;
    EXPECT_NEAR(sum, 1.0, 1e-6);
  }
}

TEST(NebulaSpectra, FilterFitsFollowTheirData) {
  FilterSet hubble = hubblePalette(dataFile("hst_wfc3_uvis_filters.csv"));
  FilterSet cie = cieFilterSet();
  for (const FilterSet* set : {&hubble, &cie})
    for (const auto& c : set->channels) {
      std::printf("%s %s: [%.4f, %.4f] um, max fit error %.2f %% of peak\n", set->name.c_str(), c.name.c_str(),
                  c.response.lambdaMinUm(), c.response.lambdaMaxUm(), 100 * c.fitMaxErrorOfPeak);
      EXPECT_LT(c.fitMaxErrorOfPeak, 0.05);
    }
  // The bands hold the lines they are named after (vacuum wavelengths).
  EXPECT_GT(hubble.channels[1].response.at(0.6564613), 0.1);
  EXPECT_GT(hubble.channels[2].response.at(0.5008239), 0.1);
  EXPECT_GT(hubble.channels[0].response.at(0.6718294), 0.1);
}

// A moved and resized passband is the fitted one, stretched about its support's centre and moved:
// P'(c + shift + (λ − c)·scale) = P(λ), its integral × scale while it stays in the band; out of
// the band or out of range, a one-line error naming it.
TEST(NebulaSpectra, PassbandEditsMoveAndStretchTheFittedResponse) {
  FilterSet hubble = hubblePalette(dataFile("hst_wfc3_uvis_filters.csv"));
  const Passband& oiii = hubble.channels[2];  // F502N
  const double centre = 0.5 * (oiii.response.lambdaMinUm() + oiii.response.lambdaMaxUm());
  auto integral = [](const Passband& b) {
    double sum = 0.0;
    for (int i = 0; i < 40000; ++i) sum += b.response.at(kBandLoUm + (kBandHiUm - kBandLoUm) * (i + 0.5) / 40000);
    return sum * (kBandHiUm - kBandLoUm) / 40000;
  };
  for (PassbandEdit e : {PassbandEdit{30.0, 1.0}, PassbandEdit{-12.5, 2.5}, PassbandEdit{0.0, 0.25}}) {
    Passband edited = editedPassband(oiii, e);
    for (int i = 0; i <= 50; ++i) {
      const double lambda = oiii.response.lambdaMinUm() + (oiii.response.lambdaMaxUm() - oiii.response.lambdaMinUm()) * i / 50;
      const double moved = centre + e.shiftNm * 1e-3 + (lambda - centre) * e.widthScale;
      EXPECT_NEAR(edited.response.at(moved), oiii.response.at(lambda), 1e-9) << e.shiftNm << " " << e.widthScale << " " << lambda;
    }
    EXPECT_NEAR(integral(edited), e.widthScale * integral(oiii), 2e-3 * integral(oiii));
  }
  // Moved past the band's red end: what is left is clipped to it.
  Passband clipped = editedPassband(oiii, {200.0, 4.0});
  EXPECT_LE(clipped.response.lambdaMaxUm(), kBandHiUm);
  EXPECT_THROW(editedPassband(hubble.channels[1], {200.0, 0.25}), Error);  // Hα at 856 nm: nothing left
  EXPECT_THROW(editedPassband(oiii, {201.0, 1.0}), Error);
  EXPECT_THROW(editedPassband(oiii, {0.0, 5.0}), Error);
  try {
    editedPassband(hubble.channels[1], {200.0, 0.25});
  } catch (const Error& x) {
    EXPECT_NE(std::string(x.what()).find("passband F656N: moved 200 nm and × 0.25 wide, nothing of it is left in 380–780 nm"),
              std::string::npos) << x.what();
  }
}

TEST(NebulaSpectra, EmissionLinesFromData) {
  auto lines = readEmissionLines(dataFile("nebula_lines.csv"));
  ASSERT_EQ(lines.size(), 15u);
  EXPECT_EQ(lines[0].name, "H-alpha");
  EXPECT_NEAR(lines[0].lambdaUm, 0.6564613, 1e-9);
}

TEST(NebulaDensity, NoiseIsDeterministicAndSeeded) {
  NoiseParameters p;
  p.resolution = 16;
  DensityGrid a = generateFbm(p, 1), b = generateFbm(p, 2);
  EXPECT_EQ(a.values, b.values);
  p.seed = 2;
  EXPECT_NE(generateFbm(p, 1).values, a.values);
  double sum = 0;
  for (float v : a.values) sum += v;
  EXPECT_GT(sum, 0.0);
}

// A bias below −amplitude leaves every voxel at 0: valid, but said (it rendered nothing unannounced).
TEST(NebulaDensity, AnEmptyGridIsWarnedOf) {
  NoiseParameters p;
  p.resolution = 8;
  EXPECT_EQ(emptyGridWarning(generateFbm(p, 1)), "");
  p.bias = -5.0;
  EXPECT_NE(emptyGridWarning(generateFbm(p, 1)).find("the density is 0 in every voxel"), std::string::npos);
  // 1.0 written big-endian reads 4.6e-41, a subnormal float: said too (it rendered black).
  DensityGrid swapped = generateFbm(p, 1);
  std::fill(swapped.values.begin(), swapped.values.end(), std::bit_cast<float>(0x0000803fu));
  EXPECT_EQ(emptyGridWarning(swapped),
            "the density is below float's smallest normal number (1.18e-38) in every voxel, the largest 4.6e-41, so the "
            "nebula neither glows nor dims what lies behind it: a file written big-endian? Density files hold "
            "little-endian float32");
  swapped.values[3] = std::numeric_limits<float>::min();
  EXPECT_EQ(emptyGridWarning(swapped), "");
}

TEST(NebulaDensity, FileRoundTrips) {
  NoiseParameters p;
  p.resolution = 8;
  DensityGrid a = generateFbm(p, 1);
  auto path = std::filesystem::path(::testing::TempDir()) / "nebula_roundtrip.density";
  writeDensityFile(path, a);
  DensityGrid b = readDensityFile(path);
  EXPECT_EQ(b.nx, 8);
  EXPECT_EQ(b.values, a.values);
}

TEST(NebulaDensity, BadFilesAreRefusedInOneLine) {
  auto bad = [](const std::string& name, const std::string& text) {
    auto path = writeTempFile(name, text);
    return std::pair{path.string(), errorOf([&] { readDensityFile(path); })};
  };
  auto [p1, e1] = bad("d1.density", "PRISM-DENSITY 2\n1 1 1\n");
  EXPECT_EQ(e1, p1 + ":1: not a Prism density file (expected the line 'prism-density 1')");
  auto [p2, e2] = bad("d2.density", "prism-density 1\n2 2\n");
  EXPECT_EQ(e2, p2 + ":2: the size line must be three integers 1…1024, 'NX NY NZ'");
  auto [p3, e3] = bad("d3.density", "prism-density 1\n1 1 2\nabcd");
  EXPECT_EQ(e3, p3 + ": byte 22: expected 8 bytes of float32 data (1×1×2), found 4");
  float negative[2] = {0.5f, -1.0f};
  auto [p4, e4] = bad("d4.density", "prism-density 1\n2 1 1\n" + std::string(reinterpret_cast<char*>(negative), 8));
  EXPECT_EQ(e4, p4 + ": byte 26: voxel (1, 0, 0) is -1: densities must lie within 0–1e+12");
  float huge[2] = {0.5f, 3.4e38f};  // overflowed the march, which blamed the output image
  auto [p5, e5] = bad("d5.density", "prism-density 1\n2 1 1\n" + std::string(reinterpret_cast<char*>(huge), 8));
  EXPECT_EQ(e5, p5 + ": byte 26: voxel (1, 0, 0) is 3.4e+38: densities must lie within 0–1e+12");
  for (const std::string& e : {e1, e2, e3, e4, e5}) EXPECT_EQ(e.find('\n'), std::string::npos);
}

// The paper's domain taken literally, λ ∈ [0, 1] µm, attenuations g ∈ [0, 1] µm: Barrès 2023
// reports a second element a ≈ 0.45 with a worst error ≈ 0.015, falling about 10× per element;
// here the error falls 2× per element (0.157 after two). Printed for the README; the reading that
// reproduces the paper is below.
TEST(NebulaBasis, GreedyOnThePapersDomain) {
  for (double spacing : {0.0, 0.1}) {
    ExpBasis b = findExpBasis(0.0, 1.0, 1.0, 1.0, 6, spacing, /*orthonormalise=*/false);
    for (std::size_t k = 0; k < b.a.size(); ++k)
      std::printf("paper domain, spacing %.2f, element %zu: a = %.4f um, max relative error %.3e\n", spacing, k + 1,
                  b.a[k], b.maxError[k]);
    for (std::size_t k = 1; k < b.a.size(); ++k) EXPECT_LT(b.maxError[k], b.maxError[k - 1]);
  }
}

// The reading that reproduces the paper's figures: optical depths τ ∈ [0, 1], so g = C_T·τ ≤ 0.56 µm,
// over λ ∈ [0.25, 1] µm, where the model's τ ∝ 1/λ holds (C_T = 0.56 µm is valid above 0.25 µm):
// the second element is a ≈ 0.45 with a worst error ≈ 0.013, and each next one at least 10× better.
TEST(NebulaBasis, GreedyReproducesThePapersFiguresWhereItsAttenuationHolds) {
  ExpBasis b = findExpBasis(0.25, 1.0, kCtUm, 1.0, 5, 0.0, /*orthonormalise=*/false);
  for (std::size_t k = 0; k < b.a.size(); ++k)
    std::printf("tau in [0, 1] over 0.25-1 um, element %zu: a = %.4f um, max relative error %.3e\n", k + 1, b.a[k],
                b.maxError[k]);
  ASSERT_EQ(b.a.size(), 5u);
  EXPECT_NEAR(b.a[1], 0.45, 0.01);
  EXPECT_GT(b.maxError[1], 0.01);
  EXPECT_LT(b.maxError[1], 0.02);
  for (std::size_t k = 2; k < b.a.size(); ++k) EXPECT_LT(b.maxError[k], b.maxError[k - 1] / 10);
}

// The band a render uses, with the spacing the renderer uses: each element at least 5× better
// (a sixth is singular in double there: the exponentials are that collinear over 0.38–0.78 µm).
TEST(NebulaBasis, GreedyOnTheVisibleBandIsOrthonormal) {
  ExpBasis b = findExpBasis(kBandLoUm, kBandHiUm, 1.0, 2.0, 5, 0.1);
  for (std::size_t k = 0; k < b.a.size(); ++k)
    std::printf("visible band, spacing 0.1, element %zu: a = %.4f um, max relative error %.3e\n", k + 1, b.a[k],
                b.maxError[k]);
  ASSERT_EQ(b.a.size(), 5u);
  EXPECT_EQ(b.a[0], 0.0);
  for (std::size_t k = 1; k < b.a.size(); ++k) EXPECT_LT(b.maxError[k], b.maxError[k - 1] / 5);
  // Orthonormal under a quadrature other than the one M was built with (Simpson, 4000 intervals),
  // for the 4 elements the renderer uses: Σⱼ M(k,j)·e^(−aⱼ/λ) cancels ~|M|·e^0 ≈ 1e5 down to ~1,
  // which costs double about 5 digits at element 4 (and 2 more at element 5, which fails this).
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double dot = 0;
      const int n = 4000;
      for (int q = 0; q <= n; ++q) {
        double l = kBandLoUm + (kBandHiUm - kBandLoUm) * q / n;
        double w = (q == 0 || q == n ? 1.0 : (q % 2 ? 4.0 : 2.0)) * (kBandHiUm - kBandLoUm) / n / 3.0;
        dot += w * b.at(i, l) * b.at(j, l);
      }
      EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 2e-5) << i << "," << j;
    }
}

}  // namespace
}  // namespace prism::nebula

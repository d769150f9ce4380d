// Spectral PRT against its 5 nm reference and RGB-PRT, the environments, the spectral basis.
#include <cmath>
#include <cstdio>
#include <array>
#include <limits>
#include <map>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.h"
#include "spectral/illuminant.h"
#include "spectral/colour_checker.h"
#include "spectral/rgb_intent.h"
#include "techniques/prt/metamer.h"
#include "techniques/prt/prt_evaluation.h"

namespace prism::prt {
namespace {

struct Macbeth {
  PrtObject object = makeColourCheckerObject(8);
  std::vector<shared::Sh25> transfer = bakeTransfer(object.mesh, {256, true});
};
const Macbeth& macbeth() {
  static const Macbeth m;
  return m;
}

TEST(SpectralBasis, EnergyGrowsToOneAndVectorsAreOrthonormal) {
  std::vector<Eigen::VectorXd> spectra;
  for (const Spectrum& s : macbeth().object.reflectances) spectra.push_back(sampleOnGrid(s));
  spectra.push_back(sampleOnGrid(illuminant("F4")));
  SpectralBasis basis(spectra);
  ASSERT_EQ(basis.available(), 25);
  for (int m = 2; m <= 25; ++m) EXPECT_GE(basis.capturedEnergy(m), basis.capturedEnergy(m - 1));
  EXPECT_NEAR(basis.capturedEnergy(25), 1.0, 1e-12);
  Eigen::MatrixXd phi = basis.leading(16);
  EXPECT_LT((phi.transpose() * phi - Eigen::MatrixXd::Identity(16, 16)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW(basis.leading(26), Error);
  EXPECT_THROW(SpectralBasis({Eigen::VectorXd::Zero(kGridWavelengths)}), Error);
}

TEST(SpectralPrt, WithABasisSpanningTheSpectraEqualsTheReference) {
  // Two reflectances and one illuminant span 3 dimensions: the basis of 3 holds the light
  // exactly, so spectral PRT is the 5 nm reference up to float sums (ΔE00 < 0.01).
  PrtObject two = macbeth().object;
  two.reflectances.resize(2);
  for (int& m : two.vertexMaterial) m %= 2;
  SpectralEnvironment env = skyGradientEnvironment("F4 sky", illuminant("F4"));
  std::vector<Eigen::VectorXd> spectra = {sampleOnGrid(two.reflectances[0]), sampleOnGrid(two.reflectances[1]),
                                          sampleOnGrid(illuminant("F4"))};
  Eigen::MatrixXd grid = environmentOnGrid(env);
  Eigen::Vector3d white = sceneWhite(grid, cie1931Observer());
  auto reference = shadeReference(two, macbeth().transfer, grid, cie1931Observer());
  auto spectral = shadeSpectral(two, macbeth().transfer, grid, cie1931Observer(), SpectralBasis(spectra).leading(3));
  EXPECT_LT(compareShading(spectral, reference, white).max2000, 0.01);
}

TEST(SpectralPrt, UnderAConstantMapTheBasisSpendsNothingOnItsEmptyBands) {
  // A constant map's 25 terms: band 0 the light, bands 1–4 rounding (~1e-5 of it). Two
  // reflectances and that light span 3 dimensions, as under the sky gradient above; scaled each
  // to unit length, the 24 empty bands took the leading functions (captured energy 0.70 at m = 8,
  // the image 9 % dim). Scaled as one group, 3 functions hold it all.
  PrtObject two = macbeth().object;
  two.reflectances.resize(2);
  for (int& m : two.vertexMaterial) m %= 2;
  const glm::vec3 colour(0.8f, 0.7f, 0.5f);
  const Spectrum light = RgbUnboundedSpectrum::fitted(colourSpace("srgb"), colour).toDense();
  std::vector<float> texels;
  for (int i = 0; i < 64 * 32; ++i) texels.insert(texels.end(), {colour.x, colour.y, colour.z});
  SpectralEnvironment map =
      equirectangularEnvironment("constant.hdr", 64, 32, texels, [&light](const glm::vec3&) { return light; });
  SpectralBasis basis({sampleOnGrid(two.reflectances[0]), sampleOnGrid(two.reflectances[1])}, {termSpectra(map)});
  EXPECT_GT(basis.capturedEnergy(3), 1.0 - 1e-8);
  Eigen::MatrixXd grid = environmentOnGrid(map);
  Eigen::Vector3d white = sceneWhite(grid, cie1931Observer());
  auto reference = shadeReference(two, macbeth().transfer, grid, cie1931Observer());
  auto spectral = shadeSpectral(two, macbeth().transfer, grid, cie1931Observer(), basis.leading(3));
  EXPECT_LT(compareShading(spectral, reference, white).max2000, 0.01);
}

TEST(SpectralPrt, SceneWhiteOfAUniformEnvironmentIsPiTimesItsColour) {
  // A perfect white facing a uniform radiance L sees irradiance πL: Y = π Σ L ȳ · 5 nm.
  Spectrum f4 = illuminant("F4");
  Eigen::Vector3d white = sceneWhite(environmentOnGrid(uniformEnvironment("F4", f4)), cie1931Observer());
  Eigen::VectorXd l = sampleOnGrid(f4);
  Eigen::MatrixXd cmf = observerOnGrid(cie1931Observer());
  Eigen::Vector3d expect = std::numbers::pi * cmf.transpose() * l * kGridStepNm;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c] / expect[c], 1.0, 1e-5);  // float sums
}

TEST(SpectralPrt, ACamerasGreenOfAWhiteIsCie1931sLuminance) {
  // Under a camera PRT's tristimulus is on the renderer's scale (absoluteTristimulusScale): a
  // perfect white under a uniform D65 sky shows G equal to CIE 1931's Y, as the deferred
  // pipeline and the path tracer show it. Raw curves gave the Nikon D850 0.85 of it. Within the
  // 5 nm grid's sampling of curves the scale integrates at 1 nm.
  const Eigen::MatrixXd grid = environmentOnGrid(uniformEnvironment("D65", illuminant("D65")));
  const double y = sceneWhite(grid, cie1931Observer())[1];
  for (const char* camera : {"nikon_d850", "sony_ilce_7m3", "canon_eos_5d_mkii"}) {
    const double g = sceneWhite(grid, observer(camera))[1];
    std::printf("%s: G of the white / CIE 1931's Y = %.5f\n", camera, g / y);
    EXPECT_NEAR(g / y, 1.0, 5e-4) << camera;
  }
}

TEST(RgbPrt, IsRefusedUnderAnyObserverButCie1931) {
  // Its colours are a colour space's, on CIE 1931; a camera's RGB went through xyzToRgb as XYZ.
  const Eigen::MatrixXd grid = environmentOnGrid(uniformEnvironment("D65", illuminant("D65")));
  const std::vector<Spectrum> white = {Spectrum::constant(1.0)};
  EXPECT_NO_THROW(projectRgb(white, grid, cie1931Observer(), colourSpace("srgb")));
  for (const char* other : {"nikon_d850", "cie1964"}) {
    try {
      projectRgb(white, grid, observer(other), colourSpace("srgb"));
      ADD_FAILURE() << other << " was not refused";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(other), std::string::npos) << e.what();
    }
  }
}

TEST(SpectralPrt, ColourCheckerUnderF4AtEightFunctionsIsWithinDeltaE94OfOne) {
  // The bound (Schwenk et al.: m = 8 "indistinguishable" from 5 nm sampling, even
  // under F-series lamps): max ΔE94 ≤ 1 over the object; RGB-PRT is reported beside it and must
  // be worse (that is the paper's point).
  PrtReport report = basisSweep(macbeth().object, macbeth().transfer, skyGradientEnvironment("F4 sky", illuminant("F4")),
                                cie1931Observer());
  ASSERT_GE(report.sweep.size(), 8u);
  for (const BasisSweepRow& row : report.sweep)
    std::printf("m=%2d energy %.6f  ΔE94 mean %.4f max %.4f  ΔE00 mean %.4f max %.4f\n", row.m, row.capturedEnergy,
                row.error.mean94, row.error.max94, row.error.mean2000, row.error.max2000);
  std::printf("RGB-PRT ΔE94 mean %.4f max %.4f  ΔE00 mean %.4f max %.4f\n", report.rgbError.mean94, report.rgbError.max94,
              report.rgbError.mean2000, report.rgbError.max2000);
  EXPECT_LE(report.sweep[7].error.max94, 1.0);
  EXPECT_GT(report.rgbError.mean94, report.sweep[7].error.mean94);
}

TEST(SpectralPrt, MetamerHalvesMatchUnderD65AndDifferUnderA) {
  // The paper's Metacow: one half of the object carries a patch, the other its metamer under D65
  // (metamer.h). Both rendered by spectral PRT (the basis of the scene's five spectra: the two
  // reflectances, D65, A, F2, so m = 5 holds them all) on the self-shadowing height field under
  // each illuminant's sky; per vertex, the two halves' colours compared. The bounds: max
  // ΔE00 ≤ 0.5 under D65, ≥ 5 under A (mean over the vertices: shadowed feet are dark, where any
  // difference shrinks); F2 reported.
  const Observer& obs = cie1931Observer();
  const ColourCheckerPatch& patch = colourChecker()[1];  // light skin
  Metamer metamer = findMetamer(patch.reflectance, illuminant("D65"), illuminant("A"), obs);
  std::vector<SpectralEnvironment> skies = {skyGradientEnvironment("D65", illuminant("D65")),
                                            skyGradientEnvironment("A", illuminant("A")),
                                            skyGradientEnvironment("F2", illuminant("F2"))};
  std::vector<DeltaEStatistics> halves =
      metamerHalves(macbeth().object, macbeth().transfer, patch.reflectance, metamer.reflectance, skies, obs);
  ASSERT_EQ(halves.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    std::printf("metamer halves under %-3s: ΔE00 mean %.4f max %.4f\n", skies[i].name.c_str(), halves[i].mean2000,
                halves[i].max2000);
  EXPECT_LE(halves[0].max2000, 0.5);
  EXPECT_GE(halves[1].mean2000, 5.0);
}

TEST(Environment, RotationTurnsTheSkyWithoutProjectingAgain) {
  // The overcast sky turned upside down by 180° about x: its SH must be those of the flipped sky
  // projected afresh (exact quadrature on both sides, 1e-5 for the float basis), and the zenith
  // now sees what the nadir saw.
  const double ground = 0.2 * 7.0 / 9.0;
  SpectralEnvironment sky = skyGradientEnvironment("sky", Spectrum::constant(1.0), 0.2);
  glm::dmat3 flip(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0);
  SpectralEnvironment turned = rotateEnvironment(sky, flip);
  ShVector direct = projectOnSh([ground](const glm::dvec3& d) { return -d.z >= 0.0 ? (1.0 - 2.0 * d.z) / 3.0 : ground; });
  EXPECT_LT((turned.terms[0].directional - direct).cwiseAbs().maxCoeff(), 1e-5);
  auto at = [](const SpectralEnvironment& e, glm::dvec3 dir) { return e.terms[0].directional.dot(evaluateSh(dir)); };
  EXPECT_NEAR(at(turned, {0, 0, 1}), at(sky, {0, 0, -1}), 1e-5);
  // A uniform environment is unchanged by any rotation.
  SpectralEnvironment uniform = uniformEnvironment("E", Spectrum::constant(1.0));
  ShVector u = rotateEnvironment(uniform, glm::dmat3(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0)).terms[0].directional;
  EXPECT_LT((u - uniform.terms[0].directional).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(Environment, AConstantEquirectangularMapIsUniformAtAnySize) {
  // Every texel the same colour: the DC coefficient's spectrum is 4π·Y_00·S = 2√π·S (the texels'
  // solid angles sum to 4π exactly; float basis, 1e-6), the higher bands vanish but for the
  // midpoint rule over the texels' cells (256 rows of them: ~5e-5 of the DC), however few texels
  // the map has (one sample a texel left a 1×1 map's bands 1–4 at 2.2× its DC).
  const glm::vec3 colour(0.5f, 0.3f, 0.2f);
  std::map<std::array<float, 3>, Spectrum> memo;
  auto toSpectrum = [&memo](const glm::vec3& rgb) {
    auto key = std::array<float, 3>{rgb.x, rgb.y, rgb.z};
    auto it = memo.find(key);
    if (it == memo.end()) it = memo.emplace(key, RgbUnboundedSpectrum::fitted(colourSpace("srgb"), rgb).toDense()).first;
    return it->second;
  };
  const Eigen::VectorXd expect = 2.0 * std::sqrt(std::numbers::pi) * sampleOnGrid(toSpectrum(colour));
  for (auto [width, height] : {std::pair{1, 1}, {2, 1}, {4, 2}, {64, 32}, {600, 300}}) {
    std::vector<float> texels;
    for (int i = 0; i < width * height; ++i) texels.insert(texels.end(), {colour.x, colour.y, colour.z});
    Eigen::MatrixXd grid = environmentOnGrid(equirectangularEnvironment("constant.exr", width, height, texels, toSpectrum));
    EXPECT_LT((grid.col(0) - expect).cwiseAbs().maxCoeff(), 1e-6 * expect.cwiseAbs().maxCoeff()) << width;
    double higher = 0.0;
    for (int k = 1; k < 25; ++k) higher = std::max(higher, grid.col(k).cwiseAbs().maxCoeff());
    EXPECT_LT(higher, 1e-4 * expect.cwiseAbs().maxCoeff()) << width << " × " << height;
    std::printf("constant %d × %d map: bands 1–4 at most %.2g of the DC\n", width, height,
                higher / expect.cwiseAbs().maxCoeff());
  }
  std::vector<float> rgb;
  for (int i = 0; i < 64 * 32; ++i) rgb.insert(rgb.end(), {colour.x, colour.y, colour.z});
  // A broken texel is named.
  rgb[3 * (5 * 64 + 7) + 1] = std::numeric_limits<float>::quiet_NaN();
  try {
    equirectangularEnvironment("bad.exr", 64, 32, rgb, toSpectrum);
    ADD_FAILURE() << "a NaN texel was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.exr: texel (7, 5)"), std::string::npos) << e.what();
  }
}

TEST(Display, SceneWhiteBecomesTheDisplaysWhite) {
  // Bradford from the scene white (F4's, far from D65) to sRGB's: the white maps to (1, 1, 1).
  Eigen::MatrixXd grid = environmentOnGrid(uniformEnvironment("F4", illuminant("F4")));
  Eigen::Vector3d white = sceneWhite(grid, cie1931Observer());
  Eigen::Vector3d rgb = displayColours({white}, white, colourSpace("srgb"))[0];
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0, 1e-3);
}

}  // namespace
}  // namespace prism::prt

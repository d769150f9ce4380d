// Textured PRT reflectance (prt_texture.h) is the untextured path's formula: a texel holding a
// material's spectrum gets the material's R̂ in each mode, up to the half floats it is stored in;
// a spectral texture's two forms agree; an RGB texture's texels are the albedo intent's spectra;
// the texture's layers hold exactly the texels the CPU twin reads.
#include "techniques/prt/prt_texture.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/packing.hpp>

#include "spectral/colour_checker.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/rgb_intent.h"
#include "spectral/table_test_support.h"
#include "techniques/prt/prt_shared.h"

namespace prism::prt {
namespace {

// The first `n` ColorChecker patches on the grid, as a 1-row samples-form texture and as the
// spectra a material would hold (linear between the grid's wavelengths).
struct Patches {
  std::shared_ptr<SpectralTexture> texture = std::make_shared<SpectralTexture>();
  std::vector<Spectrum> spectra;
};
Patches patches(int n) {
  Patches p;
  p.texture->width = n;
  p.texture->height = 1;
  p.texture->wavelengthsNm = gridWavelengthsNm();
  p.texture->basis = Eigen::MatrixXd::Identity(kGridWavelengths, kGridWavelengths);
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd rho = sampleOnGrid(colourChecker()[static_cast<std::size_t>(i)].reflectance);
    for (int k = 0; k < kGridWavelengths; ++k) p.texture->coefficients.push_back(static_cast<float>(rho[k]));
    std::vector<double> values(kGridWavelengths);
    for (int k = 0; k < kGridWavelengths; ++k) values[static_cast<std::size_t>(k)] = static_cast<float>(rho[k]);
    p.spectra.push_back(TabulatedSpectrum(gridWavelengthsNm(), values, Extrapolation::Clamp).toDense());
  }
  return p;
}

Eigen::MatrixXd f4Sky() {
  return environmentOnGrid(skyGradientEnvironment("F4", illuminant("F4")));
}

// Each texel's R̂ against the projection of the same spectrum: half's rounding (2⁻¹¹ relative,
// 2⁻²⁵ absolute below its normal range) plus float sums (1e-6 of the map row's largest value).
void expectTexelsAreTheirProjection(const PrtTextureSource& source, int texels,
                                    const std::function<std::vector<PrtProjection>(const std::vector<Spectrum>&)>& project,
                                    const std::vector<Spectrum>& spectra) {
  std::vector<PrtProjection> direct = project(spectra);
  std::vector<Eigen::MatrixXd> maps = gridReflectanceMaps(project);
  ASSERT_EQ(maps.size(), direct.size());
  for (std::size_t p = 0; p < maps.size(); ++p) {
    PrtTexelProjector projector(source, maps[p]);
    ASSERT_EQ(projector.basisCount(), direct[p].basisCount);
    for (int x = 0; x < texels; ++x) {
      shared::PrtReflectance t = projector.texel(x, 0);
      const shared::PrtReflectance& d = direct[p].reflectances[static_cast<std::size_t>(x)];
      for (int j = 0; j < projector.basisCount(); ++j) {
        for (int c = 0; c < 3; ++c) {
          const double scale = std::abs(maps[p].row(3 * j + c).maxCoeff()) + std::abs(maps[p].row(3 * j + c).minCoeff());
          EXPECT_NEAR(t.r[j][c], d.r[j][c], std::abs(d.r[j][c]) * std::ldexp(1.0, -11) + std::ldexp(1.0, -25) + 1e-6 * scale)
              << "projection " << p << ", texel " << x << ", j " << j << ", channel " << c;
        }
      }
    }
  }
}

TEST(PrtTexture, ATexelHoldingAMaterialsSpectrumHasItsProjectionInEveryMode) {
  Patches p = patches(24);
  PrtTextureSource source(p.texture);
  const Eigen::MatrixXd environment = f4Sky();
  std::vector<Eigen::VectorXd> columns;
  for (const Spectrum& s : p.spectra) columns.push_back(sampleOnGrid(s));
  const Eigen::MatrixXd basis = SpectralBasis(columns).leading(8);
  const Observer& observer = cie1931Observer();
  expectTexelsAreTheirProjection(source, 24, [&](const std::vector<Spectrum>& r) {
    return std::vector<PrtProjection>{projectSpectral(r, environment, observer, basis)};
  }, p.spectra);
  expectTexelsAreTheirProjection(source, 24, [&](const std::vector<Spectrum>& r) {
    return std::vector<PrtProjection>{projectRgb(r, environment, observer, colourSpace("srgb"))};
  }, p.spectra);
  expectTexelsAreTheirProjection(source, 24, [&](const std::vector<Spectrum>& r) {
    return projectReference(r, environment, observer);
  }, p.spectra);
}

TEST(PrtTexture, TheCoefficientsFormIsTheSamplesFormThroughItsBasis) {
  Patches p = patches(3);
  auto coefficients = std::make_shared<SpectralTexture>();
  coefficients->width = 3;
  coefficients->height = 1;
  coefficients->wavelengthsNm = gridWavelengthsNm();
  coefficients->sampled = false;
  coefficients->basis.resize(kGridWavelengths, 3);  // the three spectra, halved: coefficients 2
  for (int i = 0; i < 3; ++i) {
    coefficients->basis.col(i) = 0.5 * sampleOnGrid(p.spectra[static_cast<std::size_t>(i)]);
    for (int j = 0; j < 3; ++j) coefficients->coefficients.push_back(i == j ? 2.0f : 0.0f);
  }
  PrtTextureSource samples(p.texture), basis(coefficients);
  for (int x = 0; x < 3; ++x) EXPECT_LT((samples.gridReflectance(x, 0) - basis.gridReflectance(x, 0)).norm(), 1e-6);
  EXPECT_EQ(basis.representativeSpectra().size(), 3u);
}

TEST(PrtTexture, RgbTexelsAreTheAlbedoIntentsSpectraAndLayersHoldTheTwinsTexels) {
  const RgbToSpectrumTable& table = smallSrgbTable();
  PrtRgbTexels rgb;
  rgb.width = 3;
  rgb.height = 2;
  rgb.rgba = {255, 0, 0, 255, 0, 128, 0, 255, 255, 0, 0, 255, 20, 40, 200, 255, 255, 255, 255, 255, 0, 128, 0, 255};
  rgb.baseColour = glm::vec3(0.5f, 1.0f, 0.8f);
  PrtTextureSource source(rgb, table);
  // Texel (1, 0): sRGB (0, 128, 0) decoded, times the base colour.
  const double green = colourSpace("srgb").decode(Eigen::Vector3d(0.0, 128.0 / 255.0, 0.0)).y();
  glm::vec3 albedo = rgb.baseColour * glm::vec3(0.0f, static_cast<float>(green), 0.0f);
  EXPECT_LT((source.gridReflectance(1, 0) - sampleOnGrid(RgbAlbedoSpectrum(table, albedo).toDense())).norm(), 1e-5);
  EXPECT_EQ(source.representativeSpectra().size(), 4u);  // six texels, four colours

  const Eigen::MatrixXd environment = f4Sky();
  std::vector<Eigen::MatrixXd> maps = gridReflectanceMaps([&](const std::vector<Spectrum>& r) {
    return std::vector<PrtProjection>{projectRgb(r, environment, cie1931Observer(), colourSpace("srgb"))};
  });
  PrtTexelProjector projector(source, maps[0]);
  std::vector<std::uint16_t> one = projector.layers(1), two = projector.layers(2);
  EXPECT_EQ(one, two);
  for (int j = 0; j < 3; ++j) {
    for (int y = 0; y < 2; ++y) {
      for (int x = 0; x < 3; ++x) {
        shared::PrtReflectance t = projector.texel(x, y);
        for (int c = 0; c < 3; ++c) {
          std::size_t at = ((static_cast<std::size_t>(j) * 2 + static_cast<std::size_t>(y)) * 3 + static_cast<std::size_t>(x)) * 4;
          EXPECT_EQ(glm::unpackHalf1x16(one[at + static_cast<std::size_t>(c)]), t.r[j][c]);
        }
      }
    }
  }
}

}  // namespace
}  // namespace prism::prt

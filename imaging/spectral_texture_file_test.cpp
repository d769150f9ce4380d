#include "imaging/spectral_texture_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include "core/error.h"
#include "imaging/exr_band.h"

namespace prism::imaging {
namespace {

class SpectralTextureFile : public ::testing::Test {
 protected:
  void SetUp() override {
    mRoot = std::filesystem::path(::testing::TempDir()) / ("prism_spectral_texture_" + std::to_string(::getpid()));
    std::filesystem::remove_all(mRoot);
    std::filesystem::create_directories(mRoot);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(mRoot, ec);
  }
  // The error reading `band` written as a file, or "" when it reads.
  std::string errorOf(const ExrBand& band) {
    std::filesystem::path path = mRoot / "bad.exr";
    writeExrBand(path, band);
    try {
      readSpectralTexture(path);
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(path.string(), 0), 0u) << e.what();
      return e.what();
    }
    return "";
  }
  std::filesystem::path mRoot;
};

SpectralTexture sampledTexture() {
  SpectralTexture t;
  t.width = 3;
  t.height = 2;
  t.wavelengthsNm = {400.0, 552.5, 700.0};
  t.basis = Eigen::MatrixXd::Identity(3, 3);
  t.sampled = true;
  for (int i = 0; i < 18; ++i) t.coefficients.push_back(static_cast<float>(i) / 17.0f);
  return t;
}

// A samples-form band of one texel: channel names and values.
ExrBand oneTexel(std::vector<std::string> channels, std::vector<float> values) {
  ExrBand b;
  b.width = 1;
  b.height = 1;
  b.rows = 1;
  b.channels = std::move(channels);
  for (float v : values) b.planes.push_back({v});
  return b;
}

TEST_F(SpectralTextureFile, SamplesRoundTripUnderTheSpectralLayoutsNames) {
  SpectralTexture t = sampledTexture();
  writeSpectralTexture(mRoot / "s.exr", t);
  ExrBand header = readExrBand(mRoot / "s.exr", false);
  EXPECT_NE(std::find(header.channels.begin(), header.channels.end(), "T.552,5nm"), header.channels.end());
  EXPECT_EQ(header.attributes.at("spectralLayoutVersion"), "1.0");
  SpectralTexture back = readSpectralTexture(mRoot / "s.exr");
  EXPECT_TRUE(back.sampled);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.wavelengthsNm, t.wavelengthsNm);
  EXPECT_EQ(back.coefficients, t.coefficients);
  EXPECT_TRUE(back.basis.isIdentity(0.0));
}

TEST_F(SpectralTextureFile, CoefficientsRoundTripWithTheirBasis) {
  SpectralTexture t;
  t.width = 2;
  t.height = 1;
  t.wavelengthsNm = {380.0, 580.0, 780.0};
  t.basis.resize(3, 2);
  t.basis << 0.5, -0.25, 0.5, 0.0, 0.5, 0.3333333;
  t.sampled = false;
  t.coefficients = {1.0f, 0.5f, 0.8f, -0.2f};
  writeSpectralTexture(mRoot / "c.exr", t);
  SpectralTexture back = readSpectralTexture(mRoot / "c.exr");
  EXPECT_FALSE(back.sampled);
  EXPECT_EQ(back.wavelengthsNm, t.wavelengthsNm);
  EXPECT_EQ(back.coefficients, t.coefficients);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_FLOAT_EQ(static_cast<float>(back.basis(i, j)), static_cast<float>(t.basis(i, j)));
}

TEST_F(SpectralTextureFile, BadFilesAreOneLineErrorsNamingTheFileAndThePlace) {
  std::ofstream(mRoot / "text.exr") << "not an image";
  EXPECT_THROW(readSpectralTexture(mRoot / "text.exr"), Error);
  EXPECT_NE(errorOf(oneTexel({"R", "G", "B"}, {0.1f, 0.2f, 0.3f})).find("no spectral channels"), std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.500nm", "coefficient.0"}, {0.1f, 0.2f})).find("one form only"), std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.500.5nm"}, {0.1f})).find("'T.500.5nm' is not a wavelength"), std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.500um"}, {0.1f})).find("is not a wavelength"), std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.500nm", "T.500,0nm"}, {0.1f, 0.1f})).find("the same wavelength"), std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.500nm", "T.600nm"}, {0.1f, 1.5f})).find("texel (0, 0): reflectance 1.5 at 600 nm"),
            std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.500nm", "T.600nm"}, {std::numeric_limits<float>::quiet_NaN(), 0.1f}))
                .find("is not finite"),
            std::string::npos);
  // A spectrum as a CSV's must be: two wavelengths at least, not all outside 360–830 nm.
  EXPECT_NE(errorOf(oneTexel({"T.500nm"}, {0.5f})).find("a spectrum needs at least two wavelengths, the texture has 1 (500 nm)"),
            std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"T.100nm", "T.200nm"}, {0.5f, 0.5f}))
                .find("its wavelengths (100–200 nm) lie outside 360–830 nm, the range Prism renders"),
            std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"coefficient.0"}, {0.5f})).find("no string attribute prism:basisWavelengthsNm"),
            std::string::npos);
  EXPECT_NE(errorOf(oneTexel({"coefficient.1"}, {0.5f})).find("not coefficient.0 to coefficient.0"), std::string::npos);
  ExrBand b = oneTexel({"coefficient.0"}, {0.5f});
  b.attributes["prism:basisWavelengthsNm"] = "400 500";
  b.attributes["prism:basis.0"] = "1";
  EXPECT_NE(errorOf(b).find("attribute prism:basis.0: 1 values, expected 2"), std::string::npos);
  b.attributes["prism:basis.0"] = "1 x";
  EXPECT_NE(errorOf(b).find("'x' is not a finite number"), std::string::npos);
  b.attributes["prism:basis.0"] = "1 2.1";  // 0.5 · 2.1 = 1.05: beyond the basis's slack
  EXPECT_NE(errorOf(b).find("outside [0, 1]"), std::string::npos);
  b.attributes["prism:basis.0"] = "1 2.01";  // 1.005: within it
  EXPECT_EQ(errorOf(b), "");
  ExrBand rows = oneTexel({"T.500nm"}, {0.5f});
  rows.height = 2;
  EXPECT_NE(errorOf(rows).find("holds rows 0–0 of a 2-row image"), std::string::npos);
}

}  // namespace
}  // namespace prism::imaging

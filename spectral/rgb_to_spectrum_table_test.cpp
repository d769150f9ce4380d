#include "spectral/rgb_to_spectrum_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

#include "shared_cpp.h"
#include "core/error.h"
#include "spectral/rgb_to_spectrum_optimiser.h"
#include "spectral/table_test_support.h"

namespace prism::shared {
#include "sigmoid.glsl"
#include "upsampling.glsl"
}

namespace prism {
namespace {

std::filesystem::path tempPath(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / name;
}

std::string readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

std::string loadError(const std::filesystem::path& p) {
  try {
    RgbToSpectrumTable::load(p);
  } catch (const Error& e) {
    return e.what();
  }
  return "loaded";
}

TEST(RgbToSpectrumTable, SavesAndLoadsExactly) {
  auto p = tempPath("roundtrip.prismlut");
  smallSrgbTable().save(p);
  RgbToSpectrumTable loaded = RgbToSpectrumTable::load(p);
  EXPECT_EQ(loaded.gamut(), "srgb");
  EXPECT_EQ(loaded.resolution(), 12);
  EXPECT_TRUE(std::equal(loaded.data().begin(), loaded.data().end(), smallSrgbTable().data().begin()));
}

TEST(RgbToSpectrumTable, RejectsTruncatedAndCorruptFiles) {
  auto good = tempPath("good.prismlut");
  smallSrgbTable().save(good);
  std::string bytes = readBytes(good);
  auto bad = tempPath("bad.prismlut");

  writeBytes(bad, bytes.substr(0, bytes.size() - 1));
  EXPECT_NE(loadError(bad).find("truncated upsampling table"), std::string::npos) << loadError(bad);
  writeBytes(bad, bytes.substr(0, 20));
  EXPECT_NE(loadError(bad).find("truncated"), std::string::npos) << loadError(bad);
  writeBytes(bad, bytes + "x");
  EXPECT_NE(loadError(bad).find("oversized"), std::string::npos) << loadError(bad);

  std::string corrupt = bytes;
  corrupt[bytes.size() / 2] ^= 0x10;
  writeBytes(bad, corrupt);
  EXPECT_NE(loadError(bad).find("checksum"), std::string::npos) << loadError(bad);

  std::string magic = bytes;
  magic[0] = 'X';
  writeBytes(bad, magic);
  EXPECT_NE(loadError(bad).find("bad magic"), std::string::npos) << loadError(bad);

  std::string version = bytes;
  version[8] = 7;
  writeBytes(bad, version);
  EXPECT_NE(loadError(bad).find("version 7"), std::string::npos) << loadError(bad);

  std::string layout = bytes;
  layout[32] = 9;
  writeBytes(bad, layout);
  EXPECT_NE(loadError(bad).find("node layout 9"), std::string::npos) << loadError(bad);

  EXPECT_EQ(loadError(tempPath("absent.prismlut")).find(tempPath("absent.prismlut").string()), 0u);
  EXPECT_EQ(loadError(bad).rfind(bad.string() + ": ", 0), 0u) << "messages start with the file";
}

TEST(RgbToSpectrumTable, OutputDoesNotDependOnThreadCount) {
  RgbToSpectrumTable one = buildRgbToSpectrumTable({"srgb", 6, 1, {}});
  RgbToSpectrumTable two = buildRgbToSpectrumTable({"srgb", 6, 2, {}});
  EXPECT_TRUE(std::equal(one.data().begin(), one.data().end(), two.data().begin()));
}

TEST(RgbToSpectrumTable, LookupsReturnNodeCoefficientsAtNodes) {
  const RgbToSpectrumTable& t = smallSrgbTable();
  for (int block = 0; block < 3; ++block)
    for (int zi = 1; zi < t.resolution(); zi += 3)
      for (int yi = 0; yi < t.resolution(); yi += 5)
        for (int xi = 0; xi < t.resolution(); xi += 4) {
          glm::vec3 rgb = t.nodeRgb(block, zi, yi, xi);
          // Nodes with equal largest channels belong to the block lutPosition picks.
          if ((block != 0 && rgb.x >= rgb[block]) || (block == 2 && rgb.y >= rgb.z)) continue;
          glm::vec3 expected = t.coefficients(block, zi, yi, xi);
          for (glm::vec3 got : {t.lookup(rgb), t.lookupFiltered(rgb)})
            for (int c = 0; c < 3; ++c)
              EXPECT_NEAR(got[c], expected[c], 1e-4f * std::abs(expected[c]) + 1e-7f)
                  << block << " " << zi << " " << yi << " " << xi;
        }
}

TEST(RgbToSpectrumTable, AnalyticBrightnessIndexEqualsASearchOfTheNodes) {
  const int res = 64;
  std::vector<float> nodes;
  for (int k = 0; k < res; ++k) nodes.push_back(shared::lutScaleOfNode(static_cast<float>(k) / (res - 1)));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> zs(nodes);
  for (int i = 0; i < 100000; ++i) zs.push_back(unit(rng));
  for (float z : zs) {
    int searched = static_cast<int>(std::upper_bound(nodes.begin(), nodes.end(), z) - nodes.begin()) - 1;
    searched = std::clamp(searched, 0, res - 2);
    shared::LutPosition p{0, 0.5f, 0.5f, z};
    EXPECT_EQ(shared::lutCell(p, res).zi, searched) << z;
  }
}

TEST(RgbToSpectrumTable, NonFiniteAndOutOfRangeAlbedosAreSanitised) {
  const RgbToSpectrumTable& t = smallSrgbTable();
  glm::vec3 clamped = t.lookup(glm::vec3(1.0f, 0.0f, 0.25f));
  for (glm::vec3 rgb : {glm::vec3(NAN, 0.5f, 0.2f), glm::vec3(INFINITY, -INFINITY, 0.25f),
                        glm::vec3(3.0f, -1.0f, 0.25f)}) {
    for (glm::vec3 c : {t.lookup(rgb), t.lookupFiltered(rgb)})
      for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(c[i]));
  }
  EXPECT_EQ(t.lookup(glm::vec3(3.0f, -1.0f, 0.25f)), clamped);
  EXPECT_EQ(t.lookup(glm::vec3(INFINITY, -INFINITY, 0.25f)), clamped);
}

TEST(RgbToSpectrumTable, TailsBeyondTheConstrainedBandStayFlat) {
  // The raw polynomial is unconstrained beyond 730 nm and climbs for some colours; Prism's
  // upsampled reflectance holds its 730 nm value there (and its 380 nm value below).
  const RgbToSpectrumTable& t = smallSrgbTable();
  float worstRawRise = 0.0f;
  for (int block = 0; block < 3; ++block)
    for (int zi = 0; zi < t.resolution(); ++zi)
      for (int yi = 0; yi < t.resolution(); ++yi)
        for (int xi = 0; xi < t.resolution(); ++xi) {
          glm::vec3 c = t.coefficients(block, zi, yi, xi);
          float at730 = shared::upsampledReflectance(c, 730.0f);
          for (float l : {740.0f, 780.0f, 830.0f}) EXPECT_EQ(shared::upsampledReflectance(c, l), at730);
          for (float l : {360.0f, 370.0f})
            EXPECT_EQ(shared::upsampledReflectance(c, l), shared::upsampledReflectance(c, 380.0f));
          worstRawRise = std::max(worstRawRise, shared::sigmoidSpectrum(c, 830.0f) - at730);
        }
  EXPECT_GT(worstRawRise, 0.1f) << "the artefact the clamp guards against should exist in the raw model";
}

TEST(RgbToSpectrumTable, InvalidResolutionIsAnError) {
  EXPECT_THROW(RgbToSpectrumTable("srgb", 1), Error);
  EXPECT_THROW(RgbToSpectrumTable("srgb", 300), Error);
}

}  // namespace
}  // namespace prism

// The section's environment maps as files: a Radiance .hdr and an OpenEXR of the same texels are
// the same map; anything but linear sRGB is refused, naming the file. The spectral sky's keys.
#include "techniques/prt/prt_section.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <string>

#include "core/error_test_support.h"
#include "core/json_schema.h"
#include "imaging/exr_file.h"
#include "imaging/radiance_hdr.h"
#include "spectral/observer.h"

namespace prism::prt {
namespace {

std::filesystem::path mapPath(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / (std::to_string(::getpid()) + "_" + name);
}

imaging::FloatImage skyMap() {
  imaging::FloatImage map(32, 16, 3);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      for (int c = 0; c < 3; ++c)
        map.at(x, y, c) = (y < 8 ? 0.6f + 0.3f * static_cast<float>(c) : 0.2f - 0.05f * static_cast<float>(c)) *
                          (1.0f + 0.01f * static_cast<float>(x));
  return map;
}

TEST(EnvironmentMap, HdrAndExrOfTheSameTexelsAreTheSameMap) {
  const imaging::FloatImage map = skyMap();
  std::filesystem::path exr = mapPath("sky.exr"), hdr = mapPath("sky.HDR");  // either case
  imaging::writeExr(exr, map);
  imaging::writeRadianceHdr(hdr, map);
  imaging::FloatImage fromExr = readEnvironmentMap(exr), fromHdr = readEnvironmentMap(hdr);
  ASSERT_EQ(fromHdr.width, map.width);
  ASSERT_EQ(fromHdr.height, map.height);
  EXPECT_EQ(fromExr.pixels, map.pixels);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      float largest = std::max({map.at(x, y, 0), map.at(x, y, 1), map.at(x, y, 2)});
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(fromHdr.at(x, y, c), map.at(x, y, c), largest / 128.0f);
    }
  }
  std::filesystem::remove(exr);
  std::filesystem::remove(hdr);
}

TEST(EnvironmentMap, OnlyLinearSrgbIsAMap) {
  std::filesystem::path xyz = mapPath("xyz.exr");
  imaging::writeExr(xyz, skyMap(), {.colour = imaging::ColourMeaning::Xyz});
  EXPECT_EQ(errorOf([&] { readEnvironmentMap(xyz); }),
            xyz.string() + ": an environment map must be linear sRGB (Rec. 709, D65) RGB, not xyz with 3 channel(s)");
  std::filesystem::remove(xyz);
}

// A texel that is no radiance is named in its map's file (the message named the scene's key only).
TEST(EnvironmentMap, ABadTexelIsNamedInItsFile) {
  imaging::FloatImage map = skyMap();
  map.at(3, 2, 1) = -0.5f;
  const std::filesystem::path file = mapPath("negative.exr");
  imaging::writeExr(file, map);
  const schema::Document document{(file.parent_path() / "scene.json").string(), {}};
  const nlohmann::json json = {{"environment", {{"map", file.filename().string()}}}};
  EXPECT_EQ(errorOf([&] { PrtSection::parse(schema::Node(json, "/prt", document), TechniqueSections()); }),
            document.name + ": /prt/environment/map: " + file.filename().string() +
                ": texel (3, 2): channel 1 is -0.5, not a radiance within 0..1e+12");
  std::filesystem::remove(file);
}

// The section's "atmosphere" environment, parsed as the scene loader parses it: the atmosphere
// section's keys plus sun_disc, and no luminance (the sky is absolute); errors at their pointer.
std::unique_ptr<TechniqueSection> parseSection(const std::string& text) {
  static const schema::Document document{"scene.json", {}};
  nlohmann::json json = schema::parseJson(text, document.name);
  return PrtSection::parse(schema::Node(json, "/prt", document), TechniqueSections());
}

TEST(SpectralSkySection, TakesTheAtmospheresKeysAndNoLuminance) {
  auto parsed = parseSection(R"({"environment": {"atmosphere": {"sun": {"elevation": 12}, "sun_disc": false}}})");
  const auto& section = dynamic_cast<const PrtSection&>(*parsed);
  ASSERT_TRUE(section.sky);
  EXPECT_FLOAT_EQ(section.sky->atmosphere.sunElevationDeg, 12.0f);
  EXPECT_FALSE(section.sky->sunDisc);
  EXPECT_EQ(errorOf([] { parseSection(R"({"environment": {"atmosphere": {}, "luminance": 5}})"); }),
            "scene.json: /prt/environment/luminance: the spectral sky's radiance is absolute (its sun's): give an "
            "atmosphere or an illuminant, shape and luminance");
  EXPECT_EQ(errorOf([] { parseSection(R"({"environment": {"atmosphere": {}, "map": "sky.hdr"}})"); }),
            "scene.json: /prt/environment/atmosphere: give one of a map, an atmosphere, or an illuminant and shape");
  EXPECT_EQ(errorOf([] { parseSection(R"({"environment": {"atmosphere": {"ozone": -1}}})"); })
                .rfind("scene.json: /prt/environment/atmosphere/ozone: ", 0),
            0u);
  EXPECT_EQ(errorOf([] { parseSection(R"({"environment": {"atmosphere": {"sun": {"elevation": 95}}}})"); })
                .rfind("scene.json: /prt/environment/atmosphere/sun/elevation: ", 0),
            0u);
}

TEST(PrtSection, RgbPrtRefusesACameraBeforeAFrameUnlessTheFrameIsTheReference) {
  // What the forward pass's projection refuses at its draw, said before a frame's work (the
  // renderer, render, view and bench ask); the reference mode's frame draws the 5 nm reference.
  PrtSection section;
  section.mode = PrtMode::RgbPrt;
  EXPECT_NO_THROW(section.requireObserver(cie1931Observer(), false));
  EXPECT_NO_THROW(section.requireObserver(observer("nikon_d850"), true));
  EXPECT_EQ(errorOf([&] { section.requireObserver(observer("nikon_d850"), false); }),
            "PRT's rgb-prt mode carries colours defined under CIE 1931, not spectra: the camera \"nikon_d850\" needs "
            "prt.mode spectral or reference-5nm");
  section.mode = PrtMode::Spectral;
  EXPECT_NO_THROW(section.requireObserver(observer("nikon_d850"), false));
}

TEST(PrtSection, TheBenchTimesSpectralAgainstRgbPrtInOneSpectralFrame) {
  // An RGB frame draws RGB-PRT whatever the section's mode: timed there, both configurations drew
  // RGB-PRT (the first H200 run: 2.083 / 2.083 ms).
  PrtSection section;
  const TechniqueBench b = section.bench(0);
  ASSERT_EQ(b.configs.size(), 2u);
  const auto& spectral = dynamic_cast<const PrtSection&>(*b.configs[0].section);
  const auto& rgb = dynamic_cast<const PrtSection&>(*b.configs[1].section);
  EXPECT_EQ(spectral.mode, PrtMode::Spectral);
  EXPECT_EQ(spectral.basis, 8);
  EXPECT_EQ(rgb.mode, PrtMode::RgbPrt);
  for (const TechniqueBenchConfig& c : b.configs) {
    EXPECT_FALSE(c.withoutTechnique);
    EXPECT_EQ(c.settings, (std::vector<std::pair<std::string, std::string>>{
                              {"mode", "jakob-hanika"}, {"wavelengths", "16"}, {"observer", "cie1931"}}))
        << c.label;
  }
  ASSERT_EQ(b.ratios.size(), 1u);
  EXPECT_EQ(b.ratios[0].numerator, b.configs[0].label);
  EXPECT_EQ(b.ratios[0].denominator, b.configs[1].label);
}

}  // namespace
}  // namespace prism::prt

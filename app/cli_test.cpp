// The prism executable as users meet it: exit codes, one-line errors, outputs.
#include <limits>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

#include "app/cli_test_support.h"
#include "imaging/exr_file.h"
#include "imaging/png_file.h"

namespace {

using prism::app::test::Result;
using prism::app::test::run;
using prism::app::test::slurp;

// A user error: non-zero exit (not a crash), nothing on stdout, exactly one line on stderr
// that contains `needle`.
void expectOneLineError(const std::string& args, const std::string& needle, const std::string& env = "") {
  Result r = run(args, env);
  EXPECT_GT(r.exitCode, 0) << args;
  EXPECT_NE(r.exitCode, 70) << args << ": user input must not be an internal error";
  EXPECT_EQ(r.out, "") << args;
  ASSERT_FALSE(r.err.empty()) << args;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
  std::filesystem::path p = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(p) << text;
  return p;
}

// Memory running out is the machine's limit, not a bug: an error line and exit 1 (it was
// "internal error: std::bad_alloc", exit 70), nothing written. A nebula image of 8192² pixels
// under a 900 MB address space. Not under AddressSanitizer, whose shadow memory needs terabytes
// of address space.
TEST(Cli, RunningOutOfMemoryIsAnErrorOfTheEnvironment) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer cannot run under ulimit -v";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer cannot run under ulimit -v";
#endif
#endif
  const std::filesystem::path scene = writeTemp("large_nebula.json", R"({"nebula": {"density": {"noise": {"resolution": 8}},
    "stars": [{"position": [0.5, 0.5, 0.5], "temperature": 10000, "luminosity": 1}],
    "camera": {"width": 8192, "height": 8192}}})");
  const std::filesystem::path output = std::filesystem::path(::testing::TempDir()) / "large_nebula.exr";
  Result r = run("nebula render " + scene.string() + " --method reference --steps 1 -o " + output.string(),
                 "ulimit -v 900000;");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(r.err.ends_with("prism: error: out of memory (a smaller image, grid or count may fit)\n")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(Cli, HelpExitsZero) {
  Result r = run("--help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("colour"), std::string::npos);
  EXPECT_EQ(run("colour xyz --help").exitCode, 0);
}

TEST(Cli, ParseErrorsAreOneLine) {
  expectOneLineError("", "subcommand");
  expectOneLineError("colour frobnicate", "frobnicate");
  expectOneLineError("colour delta-e --lab 1,2,3 --lab 4,x,6", "--lab");
}

TEST(Cli, UnknownNamesAreOneLineErrors) {
  expectOneLineError("colour xyz --illuminant D66", "unknown illuminant 'D66'");
  expectOneLineError("colour xyz --observer cie1932", "unknown observer 'cie1932'");
  expectOneLineError("colour convert --from srgb --to adobe 0.5,0.5,0.5", "unknown colour space 'adobe'");
  expectOneLineError("colour delta-e --lab 50,0,0 --lab 50,1,1 --formula 1976", "'1976'");
  expectOneLineError("colour list lamps", "'lamps'");
}

TEST(Cli, WavelengthSettingsAreChecked) {
  expectOneLineError("colour xyz --wavelengths 6", "multiple of 4");
  expectOneLineError("colour xyz --wavelengths 16 --range 300,830", "360–830");
  expectOneLineError("colour xyz --wavelengths 16 --strategy random", "'random'");
}

TEST(Cli, BadDataFilesAreOneLineErrorsWithTheirPlace) {
  auto bad = writeTemp("bad_reflectance.csv", "wavelength_nm,value\n400,0.5\n410,0.5,3\n");
  expectOneLineError("colour xyz --reflectance " + bad.string(), bad.string() + ":3:");
  auto text = writeTemp("text_reflectance.csv", "wavelength_nm,value\n400,0.5\n410,high\n");
  expectOneLineError("colour xyz --reflectance " + text.string(), text.string() + ":3:2:");
  expectOneLineError("colour xyz --reflectance /nonexistent/r.csv", "/nonexistent/r.csv: cannot open: no such file");
  expectOneLineError("colour xyz --illuminant D65", "data file not found", "PRISM_DATA_DIR=/nonexistent");
}

TEST(Cli, DaylightOutOfRange) { expectOneLineError("colour cct 1000", "4000–25000 K"); }

TEST(Cli, ColourCommandsRefuseNumbersBeyondTheirRange) {
  expectOneLineError("colour convert --from srgb --to rec2020 1e39,0,0", "colour convert: 1e39 is beyond ±1e+12");
  expectOneLineError("colour delta-e --lab 50,0,0 --lab 1e300,0,0", "--lab: 1e300 is beyond ±1e+12");
  expectOneLineError("colour delta-e --lab -50,0,0 --lab 50,0,0", "--lab: L* -50 is negative");
  std::filesystem::path bright = writeTemp("bright_reflectance.csv", "wavelength_nm,value\n380,0.5\n700,1.5\n");
  expectOneLineError("colour xyz --reflectance " + bright.string(), "bright_reflectance.csv:3:2: value 1.5 is outside [0, 1]");
  std::filesystem::path headless = writeTemp("headless_reflectance.csv", "380,0.5\n700,0.5\n780,0.5\n");
  expectOneLineError("colour xyz --reflectance " + headless.string(), "headless_reflectance.csv:1: expected a header line");
}

TEST(Cli, DeltaEPrintsTheValue) {
  Result r = run("colour delta-e --lab 50,2.6772,-79.7751 --lab 50,0,-82.7485");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out, "2.0425\n");  // Sharma et al. 2005, pair 1
}

TEST(Cli, XyzJsonOfD65WhiteAndSampledEstimate) {
  Result r = run("colour xyz --illuminant D65 --wavelengths 400 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["xy"][0].get<double>(), 0.3127, 1e-4);
  EXPECT_NEAR(j["xyz"][1].get<double>(), 1.0, 1e-12);
  EXPECT_LT(j["sampled"]["deltaE2000"].get<double>(), 0.01);
  // Within a range the estimate is measured against that range's integral, as a frame within it
  // integrates (against the whole band every strategy read about 34, at 400 wavelengths too).
  Result banded = run("colour xyz --illuminant D65 --rgb 0.2,0.5,0.3 --wavelengths 400 --range 500,600 --json");
  ASSERT_EQ(banded.exitCode, 0) << banded.err;
  EXPECT_LT(nlohmann::json::parse(banded.out)["sampled"]["deltaE2000"].get<double>(), 0.05) << banded.out;
}

TEST(Cli, XyzOfAnRgbAlbedoRoundTripsUnderItsOwnWhite) {
  Result r = run("colour xyz --illuminant D65 --rgb 0.2,0.5,0.3 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  // sRGB (0.2, 0.5, 0.3) → XYZ by the IEC matrix: Y = 0.2126·0.2 + 0.7152·0.5 + 0.0722·0.3.
  EXPECT_NEAR(j["xyz"][1].get<double>(), 0.2126 * 0.2 + 0.7152 * 0.5 + 0.0722 * 0.3, 2e-4);
  // Black has no chromaticity (it printed the ratio of two roundings).
  Result black = run("colour xyz --illuminant D65 --rgb 0,0,0 --json");
  ASSERT_EQ(black.exitCode, 0) << black.err;
  EXPECT_TRUE(nlohmann::json::parse(black.out)["xy"].is_null()) << black.out;
  // A camera by --camera, as other commands name one, or by --observer: the same raw RGB.
  Result camera = run("colour xyz --illuminant D65 --rgb 0.2,0.5,0.3 --camera nikon_d850 --json");
  Result observer = run("colour xyz --illuminant D65 --rgb 0.2,0.5,0.3 --observer nikon_d850 --json");
  ASSERT_EQ(camera.exitCode, 0) << camera.err;
  EXPECT_EQ(camera.out, observer.out);
  expectOneLineError("colour xyz --camera cie1931", "--camera: \"cie1931\" is not a camera");
  expectOneLineError("colour xyz --camera nikon_d850 --observer cie1964", "excludes");
  // Negative encoded values convert and convert back (they were clamped to 0, "in gamut").
  Result negative = run("colour convert --from srgb --to rec2020 --json -- -0.5,0,0");
  ASSERT_EQ(negative.exitCode, 0) << negative.err;
  const nlohmann::json n = nlohmann::json::parse(negative.out);
  EXPECT_FALSE(n["inGamut"].get<bool>());
  EXPECT_LT(n["value"][0].get<double>(), 0.0);
  const nlohmann::json& v = n["value"];
  char values[96];
  std::snprintf(values, sizeof values, "%.9f,%.9f,%.9f", v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  Result back = run(std::string("colour convert --from rec2020 --to srgb --json -- ") + values);
  ASSERT_EQ(back.exitCode, 0) << back.err;
  const nlohmann::json b = nlohmann::json::parse(back.out)["value"];
  EXPECT_NEAR(b[0].get<double>(), -0.5, 1e-6);
  EXPECT_NEAR(b[1].get<double>(), 0.0, 1e-6);
  EXPECT_NEAR(b[2].get<double>(), 0.0, 1e-6);
}

TEST(Cli, ConvertSrgbToRec2020) {
  Result r = run("colour convert --from srgb --to rec2020 --linear 1,0,0 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["value"][0].get<double>(), 0.6274, 1e-4);  // BT.2087-0
  EXPECT_TRUE(j["inGamut"].get<bool>());
  Result back = run("colour convert --from rec2020 --to srgb --linear 0,1,0 --json");
  EXPECT_FALSE(nlohmann::json::parse(back.out)["inGamut"].get<bool>());
  // D65's white as `colour xyz` prints it, to six places, is sRGB's white (it read 1.000071, out of
  // gamut); scene-linear ACES takes light above 1, a display space does not.
  auto inGamut = [](const std::string& args) {
    Result r = run("colour convert " + args + " --json");
    EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
    return nlohmann::json::parse(r.out)["inGamut"].get<bool>();
  };
  EXPECT_TRUE(inGamut("--from xyz --to srgb 0.950470,1.000000,1.088827"));
  EXPECT_TRUE(inGamut("--from acescg --to aces2065-1 2,2,2"));
  EXPECT_FALSE(inGamut("--from acescg --to srgb --linear 2,2,2"));
  EXPECT_FALSE(inGamut("--from xyz --to srgb 0.950470,1.01,1.088827"));
  EXPECT_FALSE(inGamut("--from xyz --to srgb 0,0,0.0009"));  // dark, and no colour at all: Z alone
  // Into ACEScg (white near D60): adapted, D65's white is ACEScg's; with none, as `chart` takes it,
  // it stays D65's (bluer than D60: more B than R), and the XYZ is the same.
  Result adapted = run("colour convert --from srgb --to acescg --linear 1,1,1 --json");
  Result none = run("colour convert --from srgb --to acescg --linear 1,1,1 --json --adaptation none");
  ASSERT_EQ(none.exitCode, 0) << none.err;
  const nlohmann::json a = nlohmann::json::parse(adapted.out)["value"], n = nlohmann::json::parse(none.out)["value"];
  EXPECT_NEAR(a[0].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR(a[2].get<double>(), 1.0, 1e-6);
  EXPECT_GT(n[2].get<double>(), n[0].get<double>() + 0.05);
  Result xyz = run("colour convert --from acescg --to xyz --linear " + std::to_string(n[0].get<double>()) + "," +
                   std::to_string(n[1].get<double>()) + "," + std::to_string(n[2].get<double>()) + " --json");
  EXPECT_NEAR(nlohmann::json::parse(xyz.out)["value"][0].get<double>(), 0.95047, 1e-4);  // D65's X, Y = 1
}

TEST(Cli, CctWritesACsvSpectrumAtomically) {
  std::filesystem::path out = std::filesystem::path(::testing::TempDir()) / "cct" / "d65.csv";
  Result r = run("colour cct 6504 --step 5 -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::string csv = slurp(out);
  EXPECT_EQ(csv.rfind("wavelength_nm,value\n360,", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 95);
  EXPECT_EQ(r.out, "wrote " + out.string() + "\n");
  // A step that does not reach 830 nm ends there all the same (7 nm ended at 829).
  const std::string seven = run("colour cct 6504 --step 7").out;
  EXPECT_NE(seven.find("\n829,"), std::string::npos);
  EXPECT_EQ(seven.substr(seven.rfind('\n', seven.size() - 2) + 1, 4), "830,") << seven;
}

// A lamp of one's own, as a scene's {"csv": …} light: the same colours as the lamp by its name.
TEST(Cli, ColourCommandsTakeALampFromASpectrumFile) {
  std::filesystem::path lamp = std::filesystem::path(::testing::TempDir()) / "lamp" / "daylight_5000.csv";
  ASSERT_EQ(run("colour cct 5000 --step 1 -o " + lamp.string()).exitCode, 0);
  Result byName = run("colour xyz --illuminant daylight:5000 --rgb 0.2,0.5,0.3 --json");
  Result byFile = run("colour xyz --illuminant " + lamp.string() + " --rgb 0.2,0.5,0.3 --json");
  ASSERT_EQ(byFile.exitCode, 0) << byFile.err;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(nlohmann::json::parse(byFile.out)["xyz"][c].get<double>(),
                nlohmann::json::parse(byName.out)["xyz"][c].get<double>(), 1e-5);
  auto orange = writeTemp("orange.csv", "wavelength_nm,value\n400,0.1\n550,0.3\n700,0.7\n");
  Result metamer = run("colour metamer --reflectance " + orange.string() + " --match " + lamp.string() + " --target A --json");
  EXPECT_EQ(metamer.exitCode, 0) << metamer.err;
  auto negative = writeTemp("negative_lamp.csv", "wavelength_nm,value\n400,1\n500,-1\n");
  expectOneLineError("colour xyz --illuminant " + negative.string(), "--illuminant: " + negative.string() + ":3:2: value -1 is negative");
  // As a scene refuses it: a lamp that gives no light has no colour (it printed nan, exit 0).
  auto dark = writeTemp("dark_lamp.csv", "wavelength_nm,value\n400,0\n700,0\n");
  expectOneLineError("colour xyz --illuminant " + dark.string(), dark.string() + ": the lamp has no luminous power");
}

// A scene lit by a lamp of one's own is balanced to that lamp's file as to a named one (only
// names were taken); a name off by letter case is refused with the spelling it most likely meant.
TEST(Cli, RenderBalancesTheWhiteOfALampFile) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "white_balance_file";
  const std::filesystem::path lamp = dir / "daylight_5000.csv";
  ASSERT_EQ(run("colour cct 5000 --step 1 -o " + lamp.string()).exitCode, 0);
  const std::string render = "render " + std::string(PRISM_SCENES_DIR) + "/spheres_d65.json --width 32 --height 18 ";
  auto balanced = [&](const std::string& wb, const std::string& name) {
    Result r = run(render + "--white-balance " + wb + " -o " + (dir / name).string());
    EXPECT_EQ(r.exitCode, 0) << wb << ": " << r.err;
    return prism::imaging::readPng8(dir / name);
  };
  const prism::imaging::PngImage byName = balanced("daylight:5000", "by_name.png");
  const prism::imaging::PngImage byFile = balanced(lamp.string(), "by_file.png");
  const prism::imaging::PngImage unbalanced = balanced("none", "none.png");
  int worst = 0, moved = 0;
  for (std::size_t i = 0; i < byName.rgba().size(); ++i) {
    worst = std::max(worst, std::abs(int(byName.rgba()[i]) - int(byFile.rgba()[i])));
    moved = std::max(moved, std::abs(int(byName.rgba()[i]) - int(unbalanced.rgba()[i])));
  }
  EXPECT_LE(worst, 1);
  EXPECT_GT(moved, 10);  // the balance did something
  expectOneLineError(render + "-o x.png --white-balance d65", "white-balance: unknown illuminant 'd65' (did you mean 'D65'?)");
  expectOneLineError(render + "-o x.png --white-balance blackbody:100",
                     "white-balance: blackbody: temperature must be within 500–1000000 K, got 100");
}

TEST(Cli, CameraMatrixAndLists) {
  Result r = run("colour camera-matrix --camera nikon_d850 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_LT(nlohmann::json::parse(r.out)["meanDeltaE2000"].get<double>(), 3.0);
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  // Under a narrow LED the chart pins the matrix down in one direction alone: said. A light the
  // camera does not see gave NaN, exit 0 (led:830:1), or, seen through a tail of 1e-86 (led:790:5,
  // past the D850's curves), ±57 000 entries printed as a fit of 0.199 ΔE00.
  Result narrow = run("colour camera-matrix --camera nikon_d850 --illuminant led:450:20");
  ASSERT_EQ(narrow.exitCode, 0) << narrow.err;
  EXPECT_NE(narrow.err.find("prism: warning: under led:450:20 the ColorChecker's colours through nikon_d850 barely span "
                            "three dimensions"), std::string::npos) << narrow.err;
  expectOneLineError("colour camera-matrix --camera nikon_d850 --illuminant led:830:1",
                     "--illuminant: nikon_d850 does not see led:830:1 (its G of the light is below 1e-6 of D65's");
  expectOneLineError("colour camera-matrix --camera nikon_d850 --illuminant led:790:5", "nikon_d850 does not see led:790:5");
  expectOneLineError("colour xyz --camera nikon_d850 --illuminant led:830:1", "nikon_d850 does not see led:830:1");
  expectOneLineError("colour camera-matrix --camera cie1931", "not a camera");
  expectOneLineError("colour camera-matrix --camera ''", "--camera: \"\" is not a camera");
  EXPECT_EQ(nlohmann::json::parse(run("colour list cameras --json").out).size(), 20u);
}

TEST(Cli, ChartWritesTheColourChecker) {
  std::filesystem::path out = std::filesystem::path(::testing::TempDir()) / "demo" / "chart.png";
  std::filesystem::remove(out);
  Result r = run("chart -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
  EXPECT_NE(r.out.find("dark skin"), std::string::npos);
  expectOneLineError("chart -o chart.jpg", "chart.jpg: the chart is written as a .png file");
  expectOneLineError("chart -o ''", "the chart's file name is empty");
  expectOneLineError("chart -o chart.png --adaptation cat16", "(known: bradford, cat02, von-kries, none)");
}

TEST(Cli, LutAndUpsampleCheckTheirInput) {
  expectOneLineError("lut --gamut adobe -o x.prismlut", "unknown colour space 'adobe'");
  expectOneLineError("lut --res 1 -o x.prismlut", "resolution must be within 5–256");
  expectOneLineError("lut --res 4 -o x.prismlut", "resolution must be within 5–256");
  expectOneLineError("upsample --rgb 0.5,0.5", "--rgb");
  expectOneLineError("upsample --rgb 0.5,0.5,0.5 --wavelengths 300:830:5", "--wavelengths");
  expectOneLineError("upsample --rgb 0.5,0.5,0.5 --wavelengths 360:830:1e-9", "at most 47001 wavelengths");
  expectOneLineError("upsample --rgb 0.5,0.5,0.5 --intent emission", "'emission'");
  expectOneLineError("upsample --rgb 0.5,0.5,0.5 --method smits", "'smits'");
}

TEST(Cli, UpsampleBoxMethodGivesTheThreeBands) {
  Result r = run("upsample --rgb 0.8,0.5,0.2 --method box --wavelengths 450:600:75 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["spectrum"].size(), 3u);
  EXPECT_FLOAT_EQ(j["spectrum"][0][1].get<float>(), 0.2f);
  EXPECT_FLOAT_EQ(j["spectrum"][1][1].get<float>(), 0.5f);
  EXPECT_FLOAT_EQ(j["spectrum"][2][1].get<float>(), 0.8f);
}

TEST(Cli, LutWritesATableAndUpsampleBuildsItsCache) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "cli_lut";
  std::filesystem::remove_all(dir);
  Result lut = run("lut --gamut srgb --res 6 -o " + (dir / "t.prismlut").string() + " --json");
  ASSERT_EQ(lut.exitCode, 0) << lut.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "t.prismlut"));
  EXPECT_NE(lut.err.find("100%"), std::string::npos) << "a progress bar on stderr";

  Result up = run("upsample --rgb 0.5,0.5,0.5 --res 6 --wavelengths 400:700:100 --json",
                  "PRISM_CACHE_DIR=" + (dir / "cache").string());
  ASSERT_EQ(up.exitCode, 0) << up.err;
  nlohmann::json j = nlohmann::json::parse(up.out);
  ASSERT_EQ(j["spectrum"].size(), 4u);
  for (const auto& sample : j["spectrum"]) EXPECT_NEAR(sample[1].get<double>(), 0.5, 0.01);
  EXPECT_FALSE(std::filesystem::is_empty(dir / "cache"));
  // The unbounded intent's own path, named, is the same as left out (it was refused).
  const std::string unbounded = "upsample --rgb 1.5,0.5,0.5 --res 6 --wavelengths 400:700:100 --intent unbounded --json";
  Result named = run(unbounded + " --path manual", "PRISM_CACHE_DIR=" + (dir / "cache").string());
  ASSERT_EQ(named.exitCode, 0) << named.err;
  EXPECT_EQ(named.out, run(unbounded, "PRISM_CACHE_DIR=" + (dir / "cache").string()).out);
}

TEST(Cli, BenchmarksRun) {
  Result r = run("bench --benchmark_filter=spectrumToXyzSampled/4$ --benchmark_min_time=0.001");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("spectrumToXyzSampled/4"), std::string::npos);
  // An empty list is refused, not taken for the default sweep (ten seconds of frames).
  expectOneLineError("bench " + std::string(PRISM_SCENES_DIR) + "/spheres_d65.json --wavelengths ''",
                     "--wavelengths: '' is not a ','-separated list of numbers");
}

}  // namespace

TEST(Cli, RenderChecksItsInputBeforeRendering) {
  const std::string scenes = PRISM_SCENES_DIR;
  expectOneLineError("render " + scenes + "/missing.json -o x.png", "missing.json");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.jpg", "x.jpg: the output must be a .png or an .exr");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o ''", "an output's file name is empty");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.png --mode rainbow", "mode: expected rgb, naive, jakob-hanika, reference or optimised4, got \"rainbow\"");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.png --wavelengths 6", "multiple of 4");
  // Sampling options a mode would ignore, without a word, before.
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.png --mode reference --range 500,600",
                     "--range 500,600: mode reference renders its own 472 wavelengths over 360–830 nm");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.png --mode rgb --wavelengths 8",
                     "--wavelengths 8: mode rgb renders three RGB channels");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.png --mode optimised4 --strategy rotated",
                     "--strategy rotated: mode optimised4 renders the sky's four optimised wavelengths");
  expectOneLineError("render " + scenes + "/spheres_d65.json -o x.png --set lights.7.intensity=1", "/lights/7");
  std::filesystem::path bad = writeTemp("malformed_scene.json", "{\"camera\": {,}}");
  expectOneLineError("render " + bad.string() + " -o x.png", "malformed_scene.json:1:");
  std::filesystem::path unknown = writeTemp("unknown_key_scene.json", "{\"camera\": {}, \"objects\": [], \"lihgts\": []}");
  expectOneLineError("render " + unknown.string() + " -o x.png", "/lihgts: unknown key");
}

// `wavelengths optimise`: the set fitted for the blue LED beats one uniform frame over the chart,
// and is what the cache holds (a second run reads it); a set far from the integral is warned of.
TEST(Cli, WavelengthsOptimiseFitsAndReports) {
  const std::string scenes = PRISM_SCENES_DIR;
  expectOneLineError("wavelengths optimise " + scenes + "/spheres_d65.json --wavelengths 128",
                     "the optimised strategy fits 4–64 wavelengths, got 128");
  Result r = run("wavelengths optimise " + scenes + "/spheres_blue_led.json --wavelengths 8 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["wavelengths_nm"].size(), 8u);
  ASSERT_EQ(j["weights_nm"].size(), 3u);
  EXPECT_TRUE(std::filesystem::exists(j["cache"].get<std::string>()));
  const nlohmann::json& errors = j["lights"][0]["delta_e2000"];
  EXPECT_LT(errors["optimised"]["colour_checker"]["mean"].get<double>(), 0.1);
  EXPECT_GT(errors["uniform"]["colour_checker"]["mean"].get<double>(), 1.0);
  Result again = run("wavelengths optimise " + scenes + "/spheres_blue_led.json --wavelengths 8 --json");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(nlohmann::json::parse(again.out)["wavelengths_nm"], j["wavelengths_nm"]);
  EXPECT_EQ(again.err.find("warning"), std::string::npos) << again.err;
  // A range is the integral's, as for every strategy: four wavelengths within 360–400 nm show the
  // light of that band as its 1 nm integral does (fitted to the whole 360–830 nm, they missed it
  // by 48 ΔE00, and a reference over that band by as much), and every strategy is measured on it.
  Result narrow = run("wavelengths optimise " + scenes + "/spheres_d65.json --wavelengths 4 --range 360,400 --json");
  ASSERT_EQ(narrow.exitCode, 0) << narrow.err;
  EXPECT_EQ(narrow.err.find("warning"), std::string::npos) << narrow.err;
  const nlohmann::json narrowReport = nlohmann::json::parse(narrow.out);
  const nlohmann::json& banded = narrowReport["lights"][0]["delta_e2000"];
  EXPECT_LT(banded["optimised"]["training_set"]["mean"].get<double>(), 1.0);
  EXPECT_LT(banded["optimised"]["training_set"]["mean"].get<double>(), banded["uniform"]["training_set"]["mean"].get<double>());
  // Too few wavelengths for the lights fit what they can, and say how far that is: four under A,
  // a blue LED and F11 at once.
  const std::string light = R"({"type": "directional", "direction": [0, -1, 0], "intensity": 1000, "spd": )";
  const std::filesystem::path three = writeTemp("three_lights.json",
      R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": {"grey": {"base_colour": [0.5, 0.5, 0.5]}},
          "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "grey"}], "lights": [)" +
      light + R"("A"}, )" + light + R"("led:450:20"}, )" + light + R"("F11"}]})");
  Result few = run("wavelengths optimise " + three.string() + " --wavelengths 4");
  ASSERT_EQ(few.exitCode, 0) << few.err;
  EXPECT_NE(few.err.find("prism: warning: the 4 wavelengths fitted over 360–830 nm show this scene's surfaces"),
            std::string::npos) << few.err;
}

// One test for everything that needs the 64³ upsampling table (built once per build folder,
// PRISM_CACHE_DIR), rendering small images.
TEST(Cli, RenderBenchAndDemoWriteTheirOutputs) {
  const std::string scenes = PRISM_SCENES_DIR;
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "render_cli";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  Result png = run("render " + scenes + "/spheres_d65.json -o " + (dir / "s.png").string() +
                   " --width 64 --height 36 --strategy rotated --frames 3");
  ASSERT_EQ(png.exitCode, 0) << png.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "s.png"));
  EXPECT_NE(png.out.find("3 frames)"), std::string::npos) << png.out;
  // Frames that cannot differ are rendered once, and the line says so; capitals name the format too.
  Result same = run("render " + scenes + "/spheres_d65.json -o " + (dir / "u.PNG").string() +
                    " --width 64 --height 36 --strategy uniform --frames 5");
  ASSERT_EQ(same.exitCode, 0) << same.err;
  EXPECT_NE(same.out.find("1 frame, not 5: the uniform strategy renders the same frame every time"),
            std::string::npos) << same.out;
  EXPECT_EQ(slurp(dir / "u.PNG").substr(1, 3), "PNG");
  Result exr = run("render " + scenes + "/conductors_d65.json -o " + (dir / "c.exr").string() +
                   " --width 64 --height 36 --mode reference");
  ASSERT_EQ(exr.exitCode, 0) << exr.err;
  EXPECT_GT(std::filesystem::file_size(dir / "c.exr"), 1000u);
  EXPECT_EQ(prism::imaging::readExr(dir / "c.exr").colour, prism::imaging::ColourMeaning::Xyz);
  // A camera as the observer: raw camera RGB in the EXR; the PNG through the fitted matrix,
  // white-balanced, tone-mapped and encoded for another display.
  Result camera = run("render " + scenes + "/spheres_led.json -o " + (dir / "cam.exr").string() +
                      " --width 64 --height 36 --camera nikon_d850");
  ASSERT_EQ(camera.exitCode, 0) << camera.err;
  const prism::imaging::ExrImage cam = prism::imaging::readExr(dir / "cam.exr");
  EXPECT_EQ(cam.colour, prism::imaging::ColourMeaning::CameraRgb);
  ASSERT_TRUE(cam.camera);
  EXPECT_EQ(cam.camera->name, "nikon_d850");
  // Under the blue LED the chart pins the camera's matrix down poorly, and render says so, as
  // `colour camera-matrix` does (it went through that matrix without a word); not under the lamp.
  EXPECT_EQ(camera.err.find("warning"), std::string::npos) << camera.err;
  Result narrow = run("render " + scenes + "/spheres_blue_led.json -o " + (dir / "narrow.png").string() +
                      " --width 16 --height 9 --camera nikon_d850");
  ASSERT_EQ(narrow.exitCode, 0) << narrow.err;
  EXPECT_NE(narrow.err.find("prism: warning: under the scene's light the ColorChecker's colours through nikon_d850 "
                            "barely span three dimensions"),
            std::string::npos) << narrow.err;
  Result display = run("render " + scenes + "/spheres_led.json -o " + (dir / "wb.png").string() +
                       " --width 64 --height 36 --camera nikon_d850 --white-balance led-globe-a19"
                       " --tonemap reinhard --display rec2020");
  ASSERT_EQ(display.exitCode, 0) << display.err;
  expectOneLineError("render " + scenes + "/spheres_led.json -o x.png --camera cie1964", "not a camera");
  // Given empty (a script's unset variable), it rendered CIE 1931 XYZ without a word.
  expectOneLineError("render " + scenes + "/spheres_led.json -o x.png --camera ''", "--camera: \"\" is not a camera");

  // The benches draw 256² shadow maps: at 2048² the sun's four cascades were most of each frame on
  // llvmpipe, and nothing held here depends on them.
  Result bench = run("bench " + scenes + "/spheres_d65.json --width 64 --height 36 --frames 4 --rounds 2 "
                     "--warmup 1 --wavelengths 4,8,16 --shadow-map-size 256 --json --plot " + (dir / "plot.svg").string());
  ASSERT_EQ(bench.exitCode, 0) << bench.err;
  nlohmann::json j = nlohmann::json::parse(bench.out);
  EXPECT_EQ(j["spectral"].size(), 3u);
  EXPECT_EQ(j["rounds"], 2);
  EXPECT_EQ(j["frames_per_round"], 2);
  EXPECT_GT(j["rgb"]["frame"].get<double>(), 0.0);
  EXPECT_TRUE(j["fit"].contains("slope_ms_per_wavelength"));
  for (const nlohmann::json& c : j["spectral"]) {
    EXPECT_LE(c["ratio_to_rgb_min"].get<double>(), c["ratio_to_rgb"].get<double>());
    EXPECT_GE(c["ratio_to_rgb_max"].get<double>(), c["ratio_to_rgb"].get<double>());
    EXPECT_TRUE(c["ratio_to_rgb_ci_low"].is_null());  // two rounds give no 95 % interval
  }
  // The renderer's own count: at least the 64³ RGB32F upsampling table (9 MB).
  EXPECT_GT(j["gpu_memory_mb"]["rgb"].get<double>(), 9.0);
  EXPECT_GT(j["still_camera_16"]["ratio_to_moving"].get<double>(), 0.0);
  // The orbiting camera draws the sun's finer cascades again where they moved, never its
  // whole-scene layer (at 256², a finer cascade's texel sometimes holds it still for a frame).
  const nlohmann::json& orbiting = j["orbiting_camera_16"];
  EXPECT_EQ(orbiting["every_shadow_map_per_frame"].get<double>(), 4.0);
  EXPECT_GT(orbiting["shadow_maps_per_frame"].get<double>(), 0.0);
  EXPECT_LE(orbiting["shadow_maps_per_frame"].get<double>(), 3.0);
  EXPECT_GT(orbiting["ratio_to_every_shadow_map"].get<double>(), 0.0);
  EXPECT_NE(slurp(dir / "plot.svg").find("<svg"), std::string::npos);
  // Under a camera or CIE 1964 the spectral configurations take it and the RGB ones CIE 1931:
  // the bench refused both, checking them against its RGB configuration.
  for (const char* observer : {"--camera nikon_d850", "--observer cie1964"}) {
    Result other = run("bench " + scenes + "/spheres_d65.json --width 16 --height 9 --frames 1 --rounds 1 --warmup 0 "
                       "--wavelengths 4 --shadow-map-size 256 " + observer);
    EXPECT_EQ(other.exitCode, 0) << observer << ": " << other.err;
  }
  // Water's lamp in-scattering is timed where a point or spot lamp scatters, not in the reef, lit
  // by the sun alone (a ratio of 1 for nothing: the bench counts the scene's lamps, not its lights).
  for (const auto& [scene, lamps] : {std::pair{scenes + "/reef.json", false},
                                     std::pair{scenes + "/../render/tests/water_lamps.json", true}}) {
    Result water = run("bench " + scene + " --width 16 --height 9 --frames 1 --rounds 1 --warmup 0 --wavelengths 16 "
                       "--shadow-map-size 256 --json");
    ASSERT_EQ(water.exitCode, 0) << scene << ": " << water.err;
    const nlohmann::json t = nlohmann::json::parse(water.out)["techniques"]["water"];
    EXPECT_TRUE(t.contains("spectral16_ratio_wet_to_dry")) << scene;
    EXPECT_EQ(t.contains("spectral16_ratio_lamp_scattering"), lamps) << scene;
  }

  Result demo = run("demo -o " + (dir / "gallery").string() + " --width 64 --height 36");
  ASSERT_EQ(demo.exitCode, 0) << demo.err;
  std::string index = slurp(dir / "gallery" / "index.html");
  EXPECT_NE(index.find("spheres_d65_spectral.png"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "gallery" / "textured_gltf_rgb.png"));
  for (const char* sky : {"sunset_rgb.png", "sunset_optimised4.png", "sunset_reference.png"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "gallery" / sky)) << sky;
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "gallery" / "colorchecker.png"));
  // The contact sheet: one cell a scene (the sky's optimised4) and two a nebula, four a row, each
  // half the render's size.
  std::size_t cells = 0;
  for (const auto& folder : {std::filesystem::path(scenes), std::filesystem::path(scenes) / "nebula"})
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".json") cells += folder.filename() == "nebula" ? 2 : 1;
  const prism::imaging::PngImage sheet = prism::imaging::readPng8(dir / "gallery" / "contact_sheet.png");
  EXPECT_EQ(sheet.width(), 4 * 32);
  EXPECT_EQ(sheet.height(), static_cast<int>((cells + 3) / 4) * 18);
  EXPECT_NE(index.find("contact_sheet.png"), std::string::npos);
  for (const char* nebula : {"nebula_hubble.png", "nebula_natural.png"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "gallery" / nebula)) << nebula;
    EXPECT_NE(index.find(nebula), std::string::npos) << nebula;
  }
  // The GPU's projection against the CPU's reference, within the issue's 2 % in both palettes.
  const std::size_t hubble = demo.out.find("against the reference: Hubble ");
  ASSERT_NE(hubble, std::string::npos) << demo.out;
  const std::size_t natural = demo.out.find(", natural ", hubble);
  ASSERT_NE(natural, std::string::npos) << demo.out;
  EXPECT_LT(std::stod(demo.out.substr(hubble + std::string("against the reference: Hubble ").size())), 2.0) << demo.out;
  EXPECT_LT(std::stod(demo.out.substr(natural + std::string(", natural ").size())), 2.0) << demo.out;
}

// The gallery's outputs, checked before any work: none of them over a file a scene reads (written
// into the scenes' folder, it replaced a scene's texture named colorchecker.png, exit 0), none a
// folder (found after every render).
TEST(Cli, DemoRefusesOutputsOverItsInputsBeforeWork) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "demo_inputs";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "scenes");
  std::filesystem::copy_file(std::string(PRISM_SCENES_DIR) + "/models/tiles_base_colour.png",
                             dir / "scenes" / "colorchecker.png");
  std::ofstream(dir / "scenes" / "a.json") << R"({"camera": {"position": [0, 1, 4], "target": [0, 0, 0]},
    "lights": [{"type": "directional", "direction": [0, -1, -0.5], "spd": "D65", "intensity": 3}],
    "materials": {"m": {"base_colour_texture": "colorchecker.png"}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "m"}]})";
  const std::string texture = slurp(dir / "scenes" / "colorchecker.png");
  const std::string scenes = " --scenes " + (dir / "scenes").string() + " --width 16 --height 16";
  expectOneLineError("demo -o " + (dir / "scenes").string() + scenes,
                     "colorchecker.png: is also a file the scene reads");
  EXPECT_EQ(slurp(dir / "scenes" / "colorchecker.png"), texture);
  std::filesystem::create_directories(dir / "gallery" / "index.html");
  expectOneLineError("demo -o " + (dir / "gallery").string() + scenes, "index.html: is a folder");
  EXPECT_FALSE(std::filesystem::exists(dir / "gallery" / "colorchecker.png"));
}

TEST(Cli, AtmosphereCommandsCheckTheirInput) {
  expectOneLineError("atmosphere evaluate --zeniths 0", "--zeniths must be within 1..512");
  expectOneLineError("atmosphere evaluate --reference-step 100", "reference step 100 nm must be within 0.5..50");
  expectOneLineError("atmosphere evaluate --wavelengths missing.json", "missing.json: cannot open");
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atmosphere_input";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.json") << R"({"sets": {"aerosols": {"lambda_nm": [300, 500, 600, 700], "weights_nm": [1, 1, 1, 1]}}})";
  expectOneLineError("atmosphere evaluate --quick --wavelengths " + (dir / "bad.json").string(),
                     "bad.json: /sets/aerosols/lambda_nm/0: expected a number in [360, 830], got 300");
  // A folder, a file of another shape, a short array, an empty name: one line each, never the
  // JSON library's words or an internal error.
  expectOneLineError("atmosphere evaluate --quick --wavelengths " + dir.string(), "atmosphere_input: is a folder, not a file");
  std::ofstream(dir / "other.json") << R"({"sets": {}})";
  expectOneLineError("atmosphere evaluate --quick --wavelengths " + (dir / "other.json").string(),
                     "other.json: /sets: missing required key 'aerosols'");
  std::ofstream(dir / "short.json") << R"({"sets": {"aerosols": {"lambda_nm": [400, 500, 600], "weights_nm": [1, 1, 1, 1]}}})";
  expectOneLineError("atmosphere evaluate --quick --wavelengths " + (dir / "short.json").string(),
                     "short.json: /sets/aerosols/lambda_nm: expected an array of 4 numbers, got [400,500,600]");
  expectOneLineError("atmosphere evaluate --quick --wavelengths ''", "--wavelengths: expected a file, got \"\"");
  // optimise refuses its output before the fit (seconds, or minutes without --quick).
  expectOneLineError("atmosphere optimise --quick -o ''", "-o: expected a file, got \"\"");
  expectOneLineError("atmosphere optimise --quick -o " + dir.string(), "atmosphere_input: is a folder");
}

TEST(Cli, ReferenceAndCompareCheckTheirInput) {
  const std::string scenes = PRISM_SCENES_DIR;
  const std::string scene = scenes + "/spheres_d65.json";
  expectOneLineError("reference " + scenes + "/missing.json -o x.exr", "missing.json");
  expectOneLineError("reference " + scene + " -o x.jpg", "x.jpg: the output must be a .png or an .exr");
  expectOneLineError("reference " + scene + " -o ''", "an output's file name is empty");
  expectOneLineError("compare a.exr b.exr --heatmap ''", "--heatmap: an output's file name is empty");
  expectOneLineError("compare a.exr b.exr --histogram '' --scale-max 5", "--histogram: an output's file name is empty");
  expectOneLineError("reference " + scene + " -o x.exr --variance v.png", "v.png: the variance image must be an .exr");
  expectOneLineError("reference " + scene + " -o x.exr --spp 0", "--spp must be within 1–1048576");
  expectOneLineError("reference " + scene + " -o x.exr --transport photons", "unknown light transport \"photons\"");
  expectOneLineError("reference " + scene + " -o x.exr --filter gauss", "unknown pixel filter \"gauss\"");
  expectOneLineError("reference " + scene + " -o x.exr --camera cie1964", "not a camera");
  expectOneLineError("reference " + scene + " -o x.exr --camera ''", "--camera: \"\" is not a camera");
  expectOneLineError("reference " + scene + " -o x.exr --range 300,700", "360–830");
  expectOneLineError("reference " + scene + " -o x.exr --set lights.0.intensity=-1", "/lights/0/intensity");
  expectOneLineError("reference " + scenes + "/sunset.json -o x.exr", "does not trace the atmosphere");
  expectOneLineError("reference " + scene + " -o v.exr --variance ./v.exr", "./v.exr: is also the image (-o)");
  // An exposure whose display white float cannot hold (2^128 overflows) is refused before any work.
  expectOneLineError("reference " + scene + " -o x.exr --ev 200", "--ev: exposure (EV100) 200 must be within ±50");
  expectOneLineError("reference " + scene + " -o x.exr --ev 1e39", "--ev: 1e39 is beyond ±1e+12");
  expectOneLineError("render " + scene + " -o x.exr --ev -60", "ev: expected an EV100 within ±50 or scene, got \"-60\"");
  expectOneLineError("render " + scene + " -o x.exr --set camera.ev100=300", "/camera/ev100");

  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "compare_input";
  std::filesystem::create_directories(dir);
  prism::imaging::FloatImage small(4, 3, 3, 0.5f), other(5, 3, 3, 0.5f);
  prism::imaging::writeExr(dir / "a.exr", small, {.colour = prism::imaging::ColourMeaning::Xyz});
  prism::imaging::writeExr(dir / "b.exr", other, {.colour = prism::imaging::ColourMeaning::Xyz});
  prism::imaging::writeExr(dir / "cam.exr", small, {.colour = prism::imaging::ColourMeaning::CameraRgb});
  const std::string a = (dir / "a.exr").string();
  expectOneLineError("compare " + a + " " + (dir / "nope.exr").string(), "nope.exr");
  expectOneLineError("compare " + a + " " + (dir / "b.exr").string(), "reference 4 × 3, test 5 × 3");
  expectOneLineError("compare " + a + " " + (dir / "cam.exr").string(), "cam.exr: a camera's raw RGB that does not say "
                     "which camera and matrix (prism:camera, prism:cameraToXyz): render it again with this Prism");
  // Each refusal says what would be taken: a nebula's palette and a variance were told to render
  // with an --observer neither has.
  prism::imaging::writeExr(dir / "palette.exr", small, {.colour = prism::imaging::ColourMeaning::OtherRgb});
  expectOneLineError("compare " + a + " " + (dir / "palette.exr").string(), "(nebula render --filters cie1931 writes XYZ)");
  prism::imaging::writeExr(dir / "xyz10.exr", small, {.colour = prism::imaging::ColourMeaning::Xyz1964});
  expectOneLineError("compare " + a + " " + (dir / "xyz10.exr").string(),
                     "xyz10.exr: holds xyz-1964 values; compare takes CIE 1931 XYZ, linear sRGB or a camera's RGB "
                     "(render it with --observer cie1931)");
  // A lone Y channel is read (the reader's own refusal names it as readable) but is no colour.
  prism::imaging::writeExr(dir / "y.exr", prism::imaging::FloatImage(4, 3, 1, 0.5f),
                           {.colour = prism::imaging::ColourMeaning::Xyz});
  const std::string y = (dir / "y.exr").string();
  expectOneLineError("compare " + y + " " + y, y + ": a lone Y channel (luminance alone); compare takes colour");
  expectOneLineError("compare " + a + " " + a + " --white -1", "--white");
  expectOneLineError("compare " + a + " " + a + " --white inf", "--white: must be a luminance within 1e-20–1e+12");
  const std::string heat = (dir / "heat.png").string();
  expectOneLineError("compare " + a + " " + a + " --heatmap " + heat + " --histogram " + heat, "is also the heat map");
  prism::imaging::writeExr(dir / "w1.exr", small, {.colour = prism::imaging::ColourMeaning::Xyz, .displayWhite = 100.0});
  prism::imaging::writeExr(dir / "w2.exr", small, {.colour = prism::imaging::ColourMeaning::Xyz, .displayWhite = 400.0});
  expectOneLineError("compare " + (dir / "w1.exr").string() + " " + (dir / "w2.exr").string(),
                     "different display whites (100 and 400 cd/m²)");
  EXPECT_EQ(run("compare " + (dir / "w1.exr").string() + " " + (dir / "w2.exr").string() + " --white 100").exitCode, 0);
  expectOneLineError("compare " + dir.string() + " " + a, dir.string() + ": is a folder, not an image");
  // Linear light against a display image measured the display transform (7.8 mean ΔE00 for one
  // render saved both ways): refused, and so is a white for two display images.
  prism::imaging::PngImage(4, 3, {128, 128, 128}).write(dir / "a.png");
  const std::string png = (dir / "a.png").string();
  expectOneLineError("compare " + a + " " + png, "is an EXR and " + png + " a PNG: compare two EXRs (linear light) or two PNGs");
  expectOneLineError("compare " + png + " " + png + " --white 100", "--white: only for EXRs");
  // An image holding NaN is refused, even against itself, rather than reported as "mean inf".
  prism::imaging::FloatImage nan = small;
  nan.pixels[3 * (4 * 2 + 1) + 1] = std::numeric_limits<float>::quiet_NaN();
  prism::imaging::writeExr(dir / "nan.exr", nan, {.colour = prism::imaging::ColourMeaning::Xyz});
  const std::string n = (dir / "nan.exr").string();
  expectOneLineError("compare " + n + " " + n, n + ": pixel (1, 2) holds nan: compare takes finite images");
}

// The reference against the rasteriser through `compare`: the same scene and exposure, so the
// files carry the same display white and compare with no --white.
TEST(Cli, ReferenceWritesWhatCompareReads) {
  const std::string scenes = PRISM_SCENES_DIR;
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "reference_cli";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string scene = scenes + "/spheres_d65.json";
  Result ref = run("reference " + scene + " -o " + (dir / "ref.exr").string() + " --variance " +
                   (dir / "var.exr").string() + " --width 48 --height 27 --spp 8 --filter centre");
  ASSERT_EQ(ref.exitCode, 0) << ref.err;
  EXPECT_NE(ref.err.find("100%"), std::string::npos) << "a progress bar on stderr";
  prism::imaging::ExrImage image = prism::imaging::readExr(dir / "ref.exr");
  EXPECT_EQ(image.colour, prism::imaging::ColourMeaning::Xyz);
  ASSERT_TRUE(image.displayWhite);
  EXPECT_NEAR(*image.displayWhite, 1.2 * std::exp2(11.7), 1.0);  // the scene's EV100
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "var.exr"));
  Result png = run("reference " + scene + " -o " + (dir / "ref.png").string() +
                   " --width 48 --height 27 --spp 2 --transport global --max-depth 3");
  ASSERT_EQ(png.exitCode, 0) << png.err;
  // A camera's PNG: `reference` fits its matrix under the scene's light, and so do merged parts,
  // which record it (merge fitted D65's and warned).
  const std::string blue = scenes + "/spheres_blue_led.json", tiny = " --width 16 --height 9 --camera nikon_d850";
  Result cameraPng = run("reference " + blue + " -o " + (dir / "cam.png").string() + tiny + " --spp 2");
  ASSERT_EQ(cameraPng.exitCode, 0) << cameraPng.err;
  EXPECT_EQ(cameraPng.err.find("warning"), std::string::npos) << cameraPng.err;
  Result cameraPart = run("reference " + blue + " -o " + (dir / "cam_part.exr").string() + tiny + " --spp 2 --samples 0:2");
  ASSERT_EQ(cameraPart.exitCode, 0) << cameraPart.err;
  Result again = run("reference " + blue + " -o " + (dir / "cam_part.exr").string() + tiny + " --spp 2 --samples 0:2");
  EXPECT_NE(again.out.find("complete (rows 0–8, samples 0:2 of 2), skipped"), std::string::npos) << again.out;
  for (const char* merge : {"cam_merged.png", "cam_merged.exr"}) {
    Result merged = run("merge " + (dir / "cam_part.exr").string() + " -o " + (dir / merge).string());
    ASSERT_EQ(merged.exitCode, 0) << merged.err;
    EXPECT_EQ(merged.err.find("warning"), std::string::npos) << merged.err;
  }
  EXPECT_EQ(slurp(dir / "cam_merged.png"), slurp(dir / "cam.png"));
  // The camera's real-time frame against its reference, in XYZ through the matrix both record (raw
  // RGB was refused).
  Result cameraRaster = run("render " + blue + " -o " + (dir / "cam_raster.exr").string() + tiny);
  ASSERT_EQ(cameraRaster.exitCode, 0) << cameraRaster.err;
  Result cameraCmp = run("compare " + (dir / "cam_merged.exr").string() + " " + (dir / "cam_raster.exr").string());
  ASSERT_EQ(cameraCmp.exitCode, 0) << cameraCmp.err;
  EXPECT_NE(cameraCmp.out.find("nikon_d850's raw RGB against nikon_d850's raw RGB, compared in CIE 1931 XYZ: a "
                               "camera's through the matrix its file records"),
            std::string::npos)
      << cameraCmp.out;
  // Each side through its own matrix: the camera against the eye (CIE 1931 XYZ) shows the camera's
  // own colour error, about its ColorChecker fit's under D65 (mean 0.96 ΔE00; its raw RGB taken as
  // XYZ would be tens), and one camera under two lights, or two cameras, compare too (they were
  // refused: only frames of one camera through one matrix were taken).
  const std::string d65Tiny = " --width 16 --height 9";
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "eye_d65.exr").string() + d65Tiny).exitCode, 0);
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "cam_d65.exr").string() + tiny).exitCode, 0);
  Result eye = run("compare " + (dir / "eye_d65.exr").string() + " " + (dir / "cam_d65.exr").string() + " --json");
  ASSERT_EQ(eye.exitCode, 0) << eye.err;
  nlohmann::json eyeJson = nlohmann::json::parse(eye.out);
  EXPECT_FALSE(eyeJson.contains("reference_camera"));
  EXPECT_EQ(eyeJson["test_camera"], "nikon_d850");
  EXPECT_GT(eyeJson["mean_delta_e"].get<double>(), 0.1);
  EXPECT_LT(eyeJson["mean_delta_e"].get<double>(), 1.5);
  Result canon = run("render " + blue + " -o " + (dir / "canon.exr").string() + " --width 16 --height 9 --camera canon_eos_5d");
  ASSERT_EQ(canon.exitCode, 0) << canon.err;
  Result cameras = run("compare " + (dir / "cam_raster.exr").string() + " " + (dir / "canon.exr").string() + " --json");
  ASSERT_EQ(cameras.exitCode, 0) << cameras.err;
  nlohmann::json camerasJson = nlohmann::json::parse(cameras.out);
  EXPECT_EQ(camerasJson["reference_camera"], "nikon_d850");
  EXPECT_EQ(camerasJson["test_camera"], "canon_eos_5d");
  EXPECT_LT(camerasJson["mean_delta_e"].get<double>(), 1.0);  // a near-monochromatic light: both near exact
  // Under D65 each camera's colour error shows, each through its own matrix: the D850 against the
  // EOS 5D 0.23 mean ΔE00; the EOS 5D's RGB through the D850's matrix read 4.8.
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "canon_d65.exr").string() + d65Tiny + " --camera canon_eos_5d").exitCode, 0);
  Result d65Cameras = run("compare " + (dir / "cam_d65.exr").string() + " " + (dir / "canon_d65.exr").string() + " --json");
  ASSERT_EQ(d65Cameras.exitCode, 0) << d65Cameras.err;
  EXPECT_LT(nlohmann::json::parse(d65Cameras.out)["mean_delta_e"].get<double>(), 1.0);
  Result lights = run("compare " + (dir / "cam_raster.exr").string() + " " + (dir / "cam_d65.exr").string() +
                      " --white 5000");
  ASSERT_EQ(lights.exitCode, 0) << lights.err;

  Result raster = run("render " + scene + " -o " + (dir / "raster.exr").string() + " --width 48 --height 27");
  ASSERT_EQ(raster.exitCode, 0) << raster.err;
  Result cmp = run("compare " + (dir / "ref.exr").string() + " " + (dir / "raster.exr").string() +
                   " --json --heatmap " + (dir / "heat.png").string() + " --histogram " +
                   (dir / "hist.png").string());
  ASSERT_EQ(cmp.exitCode, 0) << cmp.err;
  nlohmann::json j = nlohmann::json::parse(cmp.out);
  EXPECT_EQ(j["pixels"].get<int>(), 48 * 27);
  EXPECT_GT(j["mean_delta_e"].get<double>(), 0.0);
  EXPECT_LT(j["mean_delta_e"].get<double>(), 3.0);
  EXPECT_GE(j["max_delta_e"].get<double>(), j["p95_delta_e"].get<double>());
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "heat.png"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "hist.png"));
  Result same = run("compare " + (dir / "ref.png").string() + " " + (dir / "ref.png").string());
  ASSERT_EQ(same.exitCode, 0) << same.err;
  EXPECT_NE(same.out.find("mean 0.0000"), std::string::npos) << same.out;
  // A part of a split render is refused: a band of rows was compared as if it were the image's
  // top (mean ΔE00 55 between two bands), some of the paths under a white of 1 (37 for 13); a
  // camera's part was refused for its matrix's type, text in a part, with no word of the part.
  for (const char* part : {"--tile 1/2", "--samples 0:1", "--tile 1/2 --camera nikon_d850"}) {
    const std::filesystem::path file = dir / "part.exr";
    Result made = run("reference " + scene + " -o " + file.string() + " --width 8 --height 4 --spp 2 " + part);
    ASSERT_EQ(made.exitCode, 0) << made.err;
    expectOneLineError("compare " + file.string() + " " + file.string(),
                       "part.exr: a part of a reference render; merge the parts first (prism merge)");
  }
}

TEST(Cli, NebulaBasisRenderAndTheirErrors) {
  Result basis = run("nebula basis --spacing 0.2 --count 3");
  ASSERT_EQ(basis.exitCode, 0) << basis.err;
  EXPECT_NE(basis.out.find("0.8100"), std::string::npos) << basis.out;
  expectOneLineError("nebula basis --count 9", "--count 9: need 1 to 8 elements");
  expectOneLineError("nebula basis --domain 0.78,0.38", "--domain 0.78,0.38: need 0 ≤ LO < HI ≤ 100 µm");
  expectOneLineError("nebula basis --max-depth 0", "--max-depth 0: need a depth within (0, 1000] µm");
  expectOneLineError("nebula basis --max-exponent nan", "--max-exponent nan: need an exponent within (0, 1000] µm");
  expectOneLineError("nebula basis --spacing 3", "--spacing 3: need a spacing within [0, --max-exponent] = [0, 2] µm");
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "nebula_cli";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tiny.json") << R"({"nebula": {"density": {"noise": {"resolution": 16}},
    "stars": [{"position": [0.5, 0.5, 0.5], "temperature": 9000}], "camera": {"width": 8, "height": 8}}})";
  std::ofstream(dir / "bad.json") << R"({"nebula": {"density": {"noise": {}}, "stars": [{"position": [0, 0]}]}})";
  const std::string tiny = (dir / "tiny.json").string();
  Result render = run("nebula render " + tiny + " --method projection --steps 20 -o " + (dir / "tiny.png").string());
  ASSERT_EQ(render.exitCode, 0) << render.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "tiny.png"));
  EXPECT_EQ(render.err.find("warning"), std::string::npos) << render.err;  // its star lights the cloud from within
  // --size scales the scene's camera, as sweep's and bench's do (the scene had to be edited).
  Result sized = run("nebula render " + tiny + " --steps 20 --size 5 -o " + (dir / "sized.exr").string());
  ASSERT_EQ(sized.exitCode, 0) << sized.err;
  const prism::imaging::ExrImage sizedExr = prism::imaging::readExr(dir / "sized.exr");
  EXPECT_EQ(sizedExr.image.width, 5);
  EXPECT_EQ(sizedExr.image.height, 5);
  expectOneLineError("nebula render " + tiny + " --size 0 -o x.exr", "--size");
  // A grid coarser than 16 voxels an axis is said to make an image of its own (the stars' optical
  // depths are kept per voxel of it).
  std::ofstream(dir / "coarse.json") << R"({"nebula": {"density": {"noise": {"resolution": 4}},
    "stars": [{"position": [0.5, 0.5, 0.5], "temperature": 9000}], "camera": {"width": 8, "height": 8}}})";
  Result coarse = run("nebula render " + (dir / "coarse.json").string() + " --steps 20 -o " + (dir / "coarse.png").string());
  ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
  EXPECT_NE(coarse.err.find("prism: warning: the density grid is 4×4×4: each star's optical depth is kept per voxel"),
            std::string::npos) << coarse.err;
  // Lit from behind through thick dust, projection's light lies beyond its basis: one line says so
  // (nebula_basis_coverage.h), and a basis fitted deeper, as it advises, says nothing.
  std::ofstream(dir / "backlit.json") << R"({"nebula": {"density": {"noise": {"resolution": 16, "bias": 0.8}},
    "extinction": 25, "emission": 0, "stars": [{"position": [0.5, 0.5, 1.4], "temperature": 9000}],
    "camera": {"width": 8, "height": 8}}})";
  const std::string backlit = (dir / "backlit.json").string();
  // (120 steps: each within τ = 0.5, or the march's steps are warned of too.)
  Result shallow = run("nebula render " + backlit + " --method projection --steps 120 -o " + (dir / "backlit.exr").string());
  ASSERT_EQ(shallow.exitCode, 0) << shallow.err;
  EXPECT_NE(shallow.err.find("prism: warning: up to 100 % of a pixel's star light reaches the camera through more dust "
                             "than the basis is fitted for"), std::string::npos) << shallow.err;
  Result deep = run("nebula render " + backlit + " --method projection --steps 120 --basis 6 --basis-depth 16 -o " +
                    (dir / "backlit.exr").string());
  ASSERT_EQ(deep.exitCode, 0) << deep.err;
  EXPECT_EQ(deep.err.find("warning"), std::string::npos) << deep.err;
  // `nebula sweep` says it too, and takes the deeper basis (it printed 1779 % … 68.6 % with no word).
  Result sweepShallow = run("nebula sweep " + backlit + " --steps 120 --max-basis 2");
  ASSERT_EQ(sweepShallow.exitCode, 0) << sweepShallow.err;
  EXPECT_NE(sweepShallow.err.find("prism: warning: up to 100 % of a pixel's star light reaches the camera through more "
                                  "dust than the basis is fitted for"), std::string::npos) << sweepShallow.err;
  EXPECT_NE(sweepShallow.err.find("--max-basis 6"), std::string::npos) << sweepShallow.err;
  Result sweepDeep = run("nebula sweep " + backlit + " --steps 120 --max-basis 2 --basis-depth 16");
  ASSERT_EQ(sweepDeep.exitCode, 0) << sweepDeep.err;
  EXPECT_EQ(sweepDeep.err.find("warning"), std::string::npos) << sweepDeep.err;
  expectOneLineError("nebula sweep " + backlit + " --basis-depth 0", "--basis-depth: 0 is not within (0, 16] µm");
  // A camera looking away from the cube, a nebula that gives no light: black images, said.
  std::ofstream(dir / "away.json") << R"({"nebula": {"density": {"noise": {"resolution": 16}}, "emission": 0,
    "stars": [{"position": [0.5, 0.5, 0.5], "temperature": 9000, "luminosity": 0}],
    "camera": {"position": [0.5, 0.5, -1], "target": [0.5, 0.5, -2], "width": 8, "height": 8}}})";
  Result away = run("nebula render " + (dir / "away.json").string() + " -o " + (dir / "away.exr").string());
  ASSERT_EQ(away.exitCode, 0) << away.err;
  EXPECT_NE(away.err.find("prism: warning: the camera looks away from the nebula, so its image is black"),
            std::string::npos) << away.err;
  EXPECT_NE(away.err.find("prism: warning: the nebula gives no light, it only dims what lies behind it (its own image "
                          "is black): no star of luminosity above 0 to scatter the light of, and emission 0"),
            std::string::npos) << away.err;
  // Measured against that black reference, no pixel is compared: said, not a perfect 0.
  Result awayCompare = run("nebula render " + (dir / "away.json").string() + " --compare -o " + (dir / "away.exr").string());
  ASSERT_EQ(awayCompare.exitCode, 0) << awayCompare.err;
  EXPECT_NE(awayCompare.out.find("maximum): none: the reference is black, no pixel holds light"), std::string::npos)
      << awayCompare.out;
  Result awaySweep = run("nebula sweep " + (dir / "away.json").string() + " --max-basis 2 --json");
  ASSERT_EQ(awaySweep.exitCode, 0) << awaySweep.err;
  EXPECT_EQ(nlohmann::json::parse(awaySweep.out)["max_relative_error"], nlohmann::json::parse("[null, null]"));
  // A scene's passband edit that --filters' other set cannot take: said before the work, naming both.
  std::ofstream(dir / "edited.json") << R"({"nebula": {"density": {"noise": {"resolution": 8}}, "stars": [],
    "filters": "cie1931", "passbands": [{"shift_nm": 120}, {}, {}]}})";
  expectOneLineError("nebula render " + (dir / "edited.json").string() + " --filters hubble -o x.exr",
                     "edited.json: /nebula/passbands: under --filters hubble: passband FQ672N");
  expectOneLineError("nebula render " + tiny + " --method spline -o x.png", "unknown nebula method 'spline'");
  expectOneLineError("nebula render " + tiny + " -o x.jpg", "x.jpg: the output must be .exr or .png");
  expectOneLineError("nebula render " + (dir / "bad.json").string() + " -o x.png", "bad.json: /nebula/stars/0/position");
  Result gpu = run("nebula render " + tiny + " --gpu --method light-density --steps 10 -o " + (dir / "tiny_gpu.exr").string());
  ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
  EXPECT_NE(gpu.out.find("light-density (GPU)"), std::string::npos) << gpu.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "tiny_gpu.exr"));
  Result analytic = run("nebula render " + tiny + " --gpu --method analytic --steps 10 -o " + (dir / "tiny_analytic.exr").string());
  ASSERT_EQ(analytic.exitCode, 0) << analytic.err;
  EXPECT_NE(analytic.out.find("analytic (GPU)"), std::string::npos) << analytic.out;

  // The plots: the basis's error after each element, a render's error against the basis size
  // (which falls from 1 to 3 elements on the tiny nebula too).
  Result plotted = run("nebula basis --spacing 0.2 --count 3 --plot " + (dir / "basis.svg").string());
  ASSERT_EQ(plotted.exitCode, 0) << plotted.err;
  EXPECT_NE(slurp(dir / "basis.svg").find("a2 = 0.8100"), std::string::npos);
  // A quote in the scene's name stays valid JSON (it was printed as it stood).
  std::filesystem::copy_file(dir / "tiny.json", dir / "q\"uote.json", std::filesystem::copy_options::overwrite_existing);
  Result sweep = run("nebula sweep '" + (dir / "q\"uote.json").string() + "' --steps 20 --max-basis 3 --json --plot " +
                     (dir / "sweep.svg").string());
  ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
  EXPECT_EQ(nlohmann::json::parse(sweep.out)["scene"], (dir / "q\"uote.json").string());
  const nlohmann::json errors = nlohmann::json::parse(sweep.out)["max_relative_error"];
  ASSERT_EQ(errors.size(), 3u) << sweep.out;
  EXPECT_GT(errors[0].get<double>(), errors[2].get<double>()) << sweep.out;
  EXPECT_NE(slurp(dir / "sweep.svg").find("the issue's bound, 2 %"), std::string::npos);
  expectOneLineError("nebula sweep " + tiny + " --max-basis 7", "--max-basis: 7 is not within 1..6");
  expectOneLineError("nebula sweep " + tiny + " --steps 0", "--steps: 0 is not within 1..100000");
  expectOneLineError("nebula render " + tiny + " -o x.exr --basis 7", "--basis: 7 is not within 1..6");
  expectOneLineError("nebula render " + tiny + " -o x.exr --steps -1", "--steps: -1 is not within 1..100000");
  expectOneLineError("nebula render " + tiny + " -o x.exr --light-basis 0", "--light-basis: 0 is not within 1..16");
  expectOneLineError("nebula render " + tiny + " -o x.exr --basis-depth 20", "--basis-depth: 20 is not within (0, 16] µm");
  expectOneLineError("nebula render " + tiny + " -o x.exr --method analytic --basis-depth 4",
                     "--basis-depth 4: only with --method projection or light-density; analytic projects on no basis");
  expectOneLineError("nebula render " + tiny + " -o x.exr --uniform-samples 1", "--uniform-samples: 1 is not 0 (Simpson) or within 2..1000");
  expectOneLineError("nebula render " + tiny + " -o x.exr --reference-intervals 3", "--reference-intervals: 3 is odd (Simpson's rule takes pairs)");
  expectOneLineError("nebula render " + tiny + " -o x.exr --uniform-samples 7",
                     "--uniform-samples 7: only with --method reference");
  // --compare on the reference itself: against twice its Simpson intervals (it printed nothing).
  Result converged = run("nebula render " + tiny + " --method reference --steps 10 --compare -o " + (dir / "ref.exr").string());
  ASSERT_EQ(converged.exitCode, 0) << converged.err;
  EXPECT_NE(converged.out.find("against the reference at 32 Simpson intervals"), std::string::npos) << converged.out;
  expectOneLineError("nebula basis --max-exponent inf", "--max-exponent inf: need an exponent within (0, 1000] µm");
  expectOneLineError("nebula basis --spacing nan", "--spacing nan: need a spacing within [0, --max-exponent]");
  expectOneLineError("nebula basis --spacing 1.5 --count 3", "only 2 of 3 elements found");
  // Exponents whose e^(−a/λ) vanishes over the band add no direction: the same a = 287.5 µm came
  // back as elements 2 to 6, and on a band of 1e-30 µm a = 0.005 five times.
  Result wide = run("nebula basis --max-exponent 1000 --json");
  ASSERT_EQ(wide.exitCode, 0) << wide.err;
  std::set<double> exponents;
  const nlohmann::json elements = nlohmann::json::parse(wide.out)["elements"];
  for (const nlohmann::json& e : elements) exponents.insert(e["a_um"].get<double>());
  EXPECT_EQ(exponents.size(), 6u) << wide.out;
  expectOneLineError("nebula basis --domain 1e-30,1e-29", "only 1 of 6 elements found");
  std::filesystem::create_directories(dir / "folder.svg");
  expectOneLineError("nebula sweep " + tiny + " --plot " + (dir / "folder.svg").string(), "is a folder");
  expectOneLineError("nebula sweep " + tiny + " --size 0", "--size: 0 is not within 1..8192");
  // More stars than the GPU's 3D textures hold (llvmpipe's 2 048 texels deep, the largest GPUs'
  // 16 384), said before the precomputation of their optical depths (it came after it).
  std::string many = R"({"nebula": {"density": {"noise": {"resolution": 24}}, "stars": [)";
  for (int i = 0; i < 2800; ++i) many += std::string(i ? "," : "") + R"({"position": [0.5, 0.5, 0.5], "temperature": 9000})";
  std::ofstream(dir / "many.json") << many + R"(], "camera": {"width": 8, "height": 8}}})";
  expectOneLineError("nebula render " + (dir / "many.json").string() + " --gpu -o x.png",
                     "many.json: /nebula/stars: the optical depths of 2800 stars need 700 slabs of 24 texels along z "
                     "(16800), more than this GPU's 3D textures hold");
  // The renderer's scenes too, before the table, the fit and the precomputation (30 s, then the error,
  // after their progress bars: more than one line).
  std::ofstream(dir / "many_scene.json") << R"({"camera": {"position": [0, 0, -6], "target": [0, 0, 0]}, "objects": [], )" +
                                               many.substr(1) + "]}}";
  const std::string manyScene = (dir / "many_scene.json").string();
  for (const std::string& command : {"render " + manyScene + " -o x.png", "bench " + manyScene + " --frames 1"})
    expectOneLineError(command + " --width 8 --height 8",
                       "many_scene.json: /nebula/stars: the optical depths of 2800 stars need 700 slabs of 24 texels");
  // Light-density reads none of the stars' optical depths, so it marches any number of them on the
  // GPU: 1 028 stars over 8³ voxels (257 slabs of 8, past llvmpipe's 2 048) were refused with the
  // other methods' limit, its own point being a cost that does not grow with the stars.
  std::string more = R"({"nebula": {"density": {"noise": {"resolution": 8}}, "stars": [)";
  for (int i = 0; i < 1028; ++i)
    more += std::string(i ? "," : "") + R"({"position": [)" + std::to_string(0.2 + 0.6 * i / 1027.0) +
            R"(, 0.5, 0.5], "temperature": 9000})";
  std::ofstream(dir / "more.json") << more + R"(], "camera": {"width": 8, "height": 8}}})";
  Result lightDensity =
      run("nebula render " + (dir / "more.json").string() + " --gpu --method light-density -o " + (dir / "more.exr").string());
  EXPECT_EQ(lightDensity.exitCode, 0) << lightDensity.err;
  expectOneLineError("nebula render " + (dir / "more.json").string() + " --gpu -o x.png",
                     "more.json: /nebula/stars: the optical depths of 1028 stars need 257 slabs of 8 texels along z "
                     "(2056), more than this GPU's 3D textures hold (2048); light-density's march reads none of them");
  // In a scene of the renderer, as long as the stars light no surface and no frame is the reference's.
  std::ofstream(dir / "more_scene.json") << R"({"camera": {"position": [0, 0, -6], "target": [0, 0, 0]}, "objects": [], )" +
                                                more.substr(1) + "]}}";
  const std::string moreScene = (dir / "more_scene.json").string() + " --width 8 --height 8 -o " + (dir / "more.png").string();
  Result sceneLightDensity = run("render " + moreScene + " --set nebula.method=light-density --set nebula.light_surfaces=false");
  EXPECT_EQ(sceneLightDensity.exitCode, 0) << sceneLightDensity.err;
  expectOneLineError("render " + moreScene + " --set nebula.method=light-density",
                     "more_scene.json: /nebula/stars: the optical depths of 1028 stars");
  expectOneLineError("render " + moreScene + " --set nebula.method=light-density",
                     "; the stars light surfaces, which reads them (\"light_surfaces\": false reads none)");
  expectOneLineError("render " + moreScene,
                     "; \"method\": \"light-density\" with \"light_surfaces\": false reads none of them");
  // The reference mode marches the reference: refused at its first frame, after the precomputation
  // (whose progress bars come first), nothing written.
  std::filesystem::remove(dir / "more.png");
  Result reference = run("render " + moreScene + " --set nebula.method=light-density --set nebula.light_surfaces=false --mode reference");
  EXPECT_EQ(reference.exitCode, 1);
  EXPECT_NE(reference.err.find("more_scene.json: /nebula/stars: the optical depths of 1028 stars"), std::string::npos) << reference.err;
  EXPECT_NE(reference.err.find("; the reference mode's march reads them"), std::string::npos) << reference.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "more.png"));
  expectOneLineError("nebula render " + tiny + " --method reference --reference-intervals 1024 --compare -o x.exr",
                     "--compare: the reference at 1024 Simpson intervals has no finer one");
  expectOneLineError("nebula basis --plot basis.png", "--plot basis.png: the plot is written as an .svg file");
  // `nebula density -o` writes a .density file, never over the scene (it did, exit 0) or its own grid.
  Result density = run("nebula density " + tiny + " -o " + (dir / "tiny.density").string());
  ASSERT_EQ(density.exitCode, 0) << density.err;
  std::ofstream(dir / "from_file.json") << R"({"nebula": {"density": {"file": "tiny.density"}, "stars": []}})";
  const std::string sceneBefore = slurp(dir / "tiny.json");
  expectOneLineError("nebula density " + tiny + " -o " + tiny, "the density grid is written as a .density file");
  expectOneLineError("nebula density " + tiny + " -o " + (dir / "x.png").string(), "x.png: the density grid is written");
  std::filesystem::copy_file(dir / "tiny.json", dir / "scene.density", std::filesystem::copy_options::overwrite_existing);
  expectOneLineError("nebula density " + (dir / "scene.density").string() + " -o " + (dir / "scene.density").string(),
                     "is also the scene file");
  expectOneLineError("nebula density " + (dir / "from_file.json").string() + " -o " + (dir / "tiny.density").string(),
                     "is also the scene's density file");
  EXPECT_EQ(slurp(dir / "tiny.json"), sceneBefore);
  // A renderer scene's nebula section gives its grid too (it was refused as "a scene of the
  // renderer"), the same as the nebula file with the same keys; one without a section says so.
  std::ofstream(dir / "tiny_scene.json") << R"({"camera": {"position": [0, 0, -6], "target": [0, 0, 0]}, "objects": [],
    "nebula": {"density": {"noise": {"resolution": 16}}, "stars": [{"position": [0.5, 0.5, 0.5], "temperature": 9000}]}})";
  Result sectionDensity = run("nebula density " + (dir / "tiny_scene.json").string() + " -o " +
                              (dir / "tiny_scene.density").string());
  ASSERT_EQ(sectionDensity.exitCode, 0) << sectionDensity.err;
  EXPECT_EQ(slurp(dir / "tiny_scene.density"), slurp(dir / "tiny.density"));
  std::ofstream(dir / "no_nebula.json") << R"({"camera": {"position": [0, 0, -6], "target": [0, 0, 0]}, "objects": []})";
  expectOneLineError("nebula density " + (dir / "no_nebula.json").string() + " -o " + (dir / "n.density").string(),
                     "no_nebula.json: a scene of the renderer without a \"nebula\" section: no density to write");
  EXPECT_FALSE(std::filesystem::exists(dir / "n.density"));
  // Nor does `nebula render -o` write over its scene or its density file (it did, exit 0, when
  // their names ended in .png or .exr).
  std::filesystem::copy_file(dir / "tiny.json", dir / "scene.png", std::filesystem::copy_options::overwrite_existing);
  expectOneLineError("nebula render " + (dir / "scene.png").string() + " -o " + (dir / "scene.png").string(),
                     "scene.png: is also the scene file; write it to another file");
  std::filesystem::copy_file(dir / "tiny.density", dir / "grid.exr", std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "exr_grid.json") << R"({"nebula": {"density": {"file": "grid.exr"}, "stars": []}})";
  expectOneLineError("nebula render " + (dir / "exr_grid.json").string() + " -o " + (dir / "grid.exr").string(),
                     "grid.exr: is also the scene's density file");
  EXPECT_EQ(slurp(dir / "grid.exr"), slurp(dir / "tiny.density"));
  expectOneLineError("nebula render " + tiny + " -o ''", "an output's file name is empty");

  // The GPU's timings at a size of one's own, without the CPU's columns.
  Result bench = run("nebula bench --repeats 1 --size 8 --no-cpu");
  ASSERT_EQ(bench.exitCode, 0) << bench.err;
  EXPECT_NE(bench.out.find("nebula bench: 8x8"), std::string::npos) << bench.out;
  EXPECT_NE(bench.out.find("—"), std::string::npos) << bench.out;
  expectOneLineError("nebula bench --size 0", "--size must be 1 to 8192 pixels");
}

TEST(Cli, PrtCommandsCheckTheirInput) {
  std::filesystem::path text = writeTemp("model.txt", "not a model");
  expectOneLineError("prt bake " + (std::filesystem::path(::testing::TempDir()) / "missing.json").string(), "missing.json");
  expectOneLineError("prt bake " + text.string(), "model.txt");
  expectOneLineError("prt bake " + std::string(PRISM_SCENES_DIR) + "/spheres_d65.json --samples 0", "samples");
  expectOneLineError("prt report --environment cloudy", "--environment");
  expectOneLineError("prt report --illuminant F99", "F99");
  expectOneLineError("colour metamer --reflectance 'no such patch'", "no such patch");
  // Options of another environment than the one used, refused rather than ignored.
  expectOneLineError("prt report --map sky.exr --illuminant A", "--map: the map is the environment");
  expectOneLineError("prt report --sun-elevation 10", "--sun-elevation, --sun-azimuth: only with --environment atmosphere");
  expectOneLineError("prt report --environment atmosphere --illuminant A", "--illuminant: the atmosphere is lit by its sun");
  expectOneLineError("prt report --colours-m 4", "--colours-m: only with --colours");
  expectOneLineError("prt metamers --target D65", "metamer: the match and target illuminants are the same light");
  expectOneLineError("prt bake " + std::string(PRISM_SCENES_DIR) + "/prt_metamers.json --threads 100000",
                     "--threads: Value 100000 not in range 0 to 4096");
  // Outputs: named for their format, and never the input or each other (before, checked after
  // the bake, or not at all: --plot SCENE.json replaced the scene with an SVG).
  const std::string scene = std::string(PRISM_SCENES_DIR) + "/prt_metamers.json";
  expectOneLineError("prt report --plot sweep.png", "--plot sweep.png: the plot is written as an .svg file");
  expectOneLineError("prt report --colours mesh.obj", "--colours mesh.obj: the mesh is written as a .ply file");
  const std::string svg = (std::filesystem::path(::testing::TempDir()) / "scene.svg").string();
  expectOneLineError("prt report " + svg + " --plot " + svg, "is also the input");
  const std::filesystem::path file = writeTemp("not_a_folder.txt", "");
  expectOneLineError("prt report --plot " + (file / "sweep.svg").string(), "not_a_folder.txt");
  expectOneLineError("prt bake " + scene + " --part 1/2 -o " + scene, "is also the input");
  // Nor a file the input reads: a part over a model's buffer destroyed the model (exit 0).
  const std::filesystem::path models = std::filesystem::path(::testing::TempDir()) / "prt_part_model";
  std::filesystem::remove_all(models);
  std::filesystem::create_directories(models);
  for (const char* f :
       {"tiles.gltf", "tiles.bin", "tiles_base_colour.png", "tiles_metallic_roughness.png", "tiles_normal.png"})
    std::filesystem::copy_file(std::filesystem::path(PRISM_SCENES_DIR) / "models" / f, models / f);
  const std::string buffer = slurp(models / "tiles.bin");
  expectOneLineError("prt bake " + (models / "tiles.gltf").string() + " --samples 4 --part 0/2 -o " +
                         (models / "tiles.bin").string(),
                     "tiles.bin: is also a file the scene reads");
  EXPECT_EQ(slurp(models / "tiles.bin"), buffer);
}

TEST(Cli, PrtBakeCachesAndReportSweepsTheBasis) {
  // Small sizes: the commands' plumbing, not the numbers (prt_test holds those).
  std::string cache = "PRISM_CACHE_DIR=" + (std::filesystem::path(::testing::TempDir()) / "prt_cli_cache").string();
  std::filesystem::remove_all(std::filesystem::path(::testing::TempDir()) / "prt_cli_cache");
  std::string scene = std::string(PRISM_SCENES_DIR) + "/spheres_d65.json";
  Result first = run("prt bake " + scene + " --samples 16", cache);
  ASSERT_EQ(first.exitCode, 0) << first.err;
  EXPECT_NE(first.out.find("rays/s"), std::string::npos) << first.out;
  Result second = run("prt bake " + scene + " --samples 16", cache);
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_NE(second.out.find("from the cache"), std::string::npos) << second.out;
  // The scene's own materials (base colours upsampled by the renderers' table, from the tests'
  // shared cache: a fresh cache would build it for 20 s) under the sky.
  Result sceneReport = run("prt report " + scene + " --samples 16 --json");
  ASSERT_EQ(sceneReport.exitCode, 0) << sceneReport.err;
  EXPECT_FALSE(nlohmann::json::parse(sceneReport.out)["spectral"].empty());
  // An emitter's mesh baked as PRT reflects only: the report says so, as the bake does (its light
  // was dropped unsaid).
  std::filesystem::path glowing = writeTemp("prt_glowing.json", R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0]},
    "materials": {"lamp": {"base_colour": [0.6, 0.3, 0.2], "emission": {"spd": "A", "luminance": 50}}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 0.5, "segments": 8}, "material": "lamp"}]})");
  Result glowingReport = run("prt report " + glowing.string() + " --samples 16 --json");
  ASSERT_EQ(glowingReport.exitCode, 0) << glowingReport.err;
  EXPECT_NE(glowingReport.err.find("material 'lamp' emits light, which PRT's transfer does not carry"), std::string::npos)
      << glowingReport.err;
  Result glowingBake = run("prt bake " + glowing.string() + " --samples 16", cache);
  ASSERT_EQ(glowingBake.exitCode, 0) << glowingBake.err;
  EXPECT_NE(glowingBake.err.find("material 'lamp' emits light, which PRT's transfer does not carry"), std::string::npos)
      << glowingBake.err;
  expectOneLineError("prt report --patch-vertices 4 --samples 16 --colours-m 99 --colours x.ply", "--colours-m", cache);

  // A scene's own PRT section: `prt bake` makes the bake its renderer reads (the section's
  // samples, unshadowed as it says), and `prt report` lights it with the section's environment.
  std::filesystem::path tiny = writeTemp("prt_tiny.json", R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0]},
    "materials": {"m": {"base_colour": [0.6, 0.3, 0.2]}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 0.5, "segments": 8}, "material": "m", "technique": "prt"}],
    "prt": {"environment": {"illuminant": "A", "shape": "uniform", "luminance": 100}, "samples": 8, "shadows": false}})");
  Result own = run("prt bake " + tiny.string(), cache);
  ASSERT_EQ(own.exitCode, 0) << own.err;
  EXPECT_NE(own.out.find("8 directions each (unshadowed)"), std::string::npos) << own.out;
  // The tests' shared cache, which holds the renderers' table the materials are upsampled by (the
  // fresh one above would build it: 20 s, 6 minutes under ASan).
  Result ownReport = run("prt report " + tiny.string() + " --json");
  ASSERT_EQ(ownReport.exitCode, 0) << ownReport.err;
  const nlohmann::json ownJson = nlohmann::json::parse(ownReport.out);
  EXPECT_EQ(ownJson["environment"].get<std::string>().rfind("the scene's (", 0), 0u) << ownReport.out;
  EXPECT_EQ(ownJson["samples"], 8);
  // A scene under the spectral sky as a section of its own, not PRT's, is under that sky too, its
  // sun taken in; --environment atmosphere starts from it. It was the F4 sky, and the defaults'
  // sun at 30° elevation and 180° azimuth.
  const std::string sunset = std::string(PRISM_SCENES_DIR) + "/sunset.json";
  Result sky = run("prt report " + sunset + " --samples 8 --json");
  ASSERT_EQ(sky.exitCode, 0) << sky.err;
  EXPECT_EQ(nlohmann::json::parse(sky.out)["environment"],
            "the scene's (spectral sky, sun at 3° elevation, 4° azimuth, its disc on SH-5)");
  Result moved = run("prt report " + sunset + " --samples 8 --environment atmosphere --sun-elevation 10 --json");
  ASSERT_EQ(moved.exitCode, 0) << moved.err;
  EXPECT_EQ(nlohmann::json::parse(moved.out)["environment"],
            "the scene's spectral sky, sun at 10° elevation, 4° azimuth, its disc on SH-5");
  EXPECT_EQ(moved.err.find("warning"), std::string::npos) << moved.err;
  // Past the last sunlit air in view (−15.7°) the report says what its sky is (its errors went
  // erratic, m = 16 max ΔE00 1.7 at −27° against 0.02 at −26°, without a word).
  Result night = run("prt report " + sunset + " --samples 8 --environment atmosphere --sun-elevation -20 --json");
  ASSERT_EQ(night.exitCode, 0) << night.err;
  EXPECT_NE(night.err.find("prism: warning: the sun is 20° below the horizon, past the 15.7° where the last sunlit air "
                           "leaves the sky"),
            std::string::npos) << night.err;
  // With a PRT section of another environment, that is the default, and the sky --environment
  // atmosphere's start (it took the defaults' sun at 30° and 180°).
  std::filesystem::path both = writeTemp("prt_and_sky.json", R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0]},
    "materials": {"m": {"base_colour": [0.6, 0.3, 0.2]}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 0.5, "segments": 8}, "material": "m", "technique": "prt"}],
    "prt": {"environment": {"illuminant": "A", "shape": "uniform", "luminance": 100}, "samples": 8, "shadows": false},
    "atmosphere": {"sun": {"elevation": 12, "azimuth": 40}}})");
  Result bothDefault = run("prt report " + both.string() + " --json");
  ASSERT_EQ(bothDefault.exitCode, 0) << bothDefault.err;
  EXPECT_EQ(nlohmann::json::parse(bothDefault.out)["environment"], "the scene's (A uniform)");
  Result bothSky = run("prt report " + both.string() + " --environment atmosphere --json");
  ASSERT_EQ(bothSky.exitCode, 0) << bothSky.err;
  EXPECT_EQ(nlohmann::json::parse(bothSky.out)["environment"],
            "the scene's spectral sky, sun at 12° elevation, 40° azimuth, its disc on SH-5");

  std::filesystem::path ply = std::filesystem::path(::testing::TempDir()) / "prt" / "checker.ply";
  std::filesystem::path svg = std::filesystem::path(::testing::TempDir()) / "prt" / "sweep.svg";
  Result report = run("prt report --patch-vertices 4 --samples 32 --json --colours " + ply.string() + " --plot " + svg.string(),
                      cache);
  ASSERT_EQ(report.exitCode, 0) << report.err;
  auto json = nlohmann::json::parse(report.out);
  EXPECT_EQ(json["spectral"].size(), 16u);
  EXPECT_GT(json["rgb_prt"]["mean_de94"].get<double>(), 0.0);
  EXPECT_EQ(slurp(ply).rfind("ply\n", 0), 0u);
  std::string plot = slurp(svg);
  EXPECT_EQ(plot.rfind("<svg", 0), 0u);
  std::size_t lines = 0;
  for (std::size_t at = plot.find("<polyline"); at != std::string::npos; at = plot.find("<polyline", at + 1)) ++lines;
  EXPECT_EQ(lines, 4u);  // mean and max ΔE94 and ΔE00 against m
}

TEST(Cli, ColourMetamerMatchesUnderD65AndNotUnderA) {
  Result r = run("colour metamer --reflectance 'dark skin' --under D65,A,F2 --json");
  // A patch's name as a user types it is the patch (refused, listing no name).
  Result loose = run("colour metamer --reflectance Dark_Skin --under D65,A,F2 --json");
  ASSERT_EQ(loose.exitCode, 0) << loose.err;
  EXPECT_EQ(nlohmann::json::parse(loose.out)["metamer_5nm"], nlohmann::json::parse(r.out)["metamer_5nm"]);
  EXPECT_EQ(run("colour metamer --reflectance neutral_5 --json").exitCode, 0);  // 'neutral 5 (.70 D)'
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto json = nlohmann::json::parse(r.out);
  EXPECT_LE(json["delta_e2000"]["D65"].get<double>(), 0.5);
  EXPECT_GE(json["delta_e2000"]["A"].get<double>(), 5.0);
  EXPECT_TRUE(json["delta_e2000"].contains("F2"));

  // A pair on an object through spectral PRT (small: 4 vertices a patch, 32 directions). Light
  // skin, as prt_test: dark skin's halves sit at the D65 bound (README, "Spectral PRT").
  Result halves = run("prt metamers --reflectance 'light skin' --patch-vertices 4 --samples 32 --json");
  ASSERT_EQ(halves.exitCode, 0) << halves.err;
  auto h = nlohmann::json::parse(halves.out);
  EXPECT_LE(h["halves"]["D65"]["max_de2000"].get<double>(), 0.5);
  EXPECT_GE(h["halves"]["A"]["mean_de2000"].get<double>(), 5.0);
  expectOneLineError("prt metamers --reflectance nothing", "nothing");
  expectOneLineError("colour metamer --reflectance 'dark skin' --observer canon_eos_5d", "'canon_eos_5d' is a camera");
}

TEST(Cli, PrtReportTurnsTheEnvironment) {
  // The overcast sky is symmetric about its zenith (+z): turned about z it gives the same errors;
  // turned upside down (the ground now above) it does not. A zero axis is refused.
  std::string base = "prt report --patch-vertices 4 --samples 32 --json";
  auto rgbMean = [](const Result& r) { return nlohmann::json::parse(r.out)["rgb_prt"]["mean_de94"].get<double>(); };
  Result plain = run(base), aboutZ = run(base + " --rotate 0,0,1,90"), flipped = run(base + " --rotate 1,0,0,180");
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  ASSERT_EQ(aboutZ.exitCode, 0) << aboutZ.err;
  ASSERT_EQ(flipped.exitCode, 0) << flipped.err;
  EXPECT_NEAR(rgbMean(aboutZ), rgbMean(plain), 1e-3 * rgbMean(plain));
  EXPECT_GT(std::abs(rgbMean(flipped) - rgbMean(plain)), 1e-2 * rgbMean(plain));
  expectOneLineError("prt report --rotate 0,0,0,90", "--rotate");
  expectOneLineError("prt report --rotate 1,2", "--rotate");
}

TEST(Cli, PrtReportTakesAnEquirectangularExr) {
  // A sky-like map (bright bluish top, dark warm bottom); the renderers' sRGB table from the
  // tests' shared cache. A NaN texel and an XYZ file are one-line errors naming them.
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "prt_exr";
  prism::imaging::FloatImage map(32, 16, 3);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      bool sky = y < 8;
      map.at(x, y, 0) = sky ? 0.6f : 0.2f;
      map.at(x, y, 1) = sky ? 0.8f : 0.15f;
      map.at(x, y, 2) = sky ? 1.2f : 0.1f;
    }
  prism::imaging::writeExr(dir / "sky.exr", map);
  Result r = run("prt report --patch-vertices 4 --samples 32 --json --exr " + (dir / "sky.exr").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["spectral"].size(), 16u);
  EXPECT_NE(json["environment"].get<std::string>().find("sky.exr"), std::string::npos);

  // The map of a scene's PRT section is one of the files the scene reads: no output may replace it.
  std::ofstream(dir / "mapped.json") << R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0]},
    "materials": {"m": {"base_colour": [0.5, 0.5, 0.5]}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 0.5, "segments": 8}, "material": "m", "technique": "prt"}],
    "prt": {"environment": {"map": "sky.exr"}, "samples": 8}})";
  const std::string mapped = (dir / "mapped.json").string(), sky = (dir / "sky.exr").string();
  expectOneLineError("render " + mapped + " -o " + sky, sky + ": is also a file the scene reads");
  expectOneLineError("reference " + mapped + " -o " + sky, sky + ": is also a file the scene reads");

  map.at(3, 2, 1) = std::numeric_limits<float>::quiet_NaN();
  prism::imaging::writeExr(dir / "nan.exr", map);
  expectOneLineError("prt report --exr " + (dir / "nan.exr").string(), "nan.exr: texel (3, 2)");
  prism::imaging::writeExr(dir / "xyz.exr", map, {.colour = prism::imaging::ColourMeaning::Xyz});
  expectOneLineError("prt report --exr " + (dir / "xyz.exr").string(), "linear sRGB");
}

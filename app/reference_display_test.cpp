// `prism reference` and `prism merge` write a PNG through the display options `prism render`
// takes (white balance, adaptation, tone map, display), so that a reference and a render can be
// shown alike; an EXR (linear tristimulus) refuses them, as render's does.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/cli_test_support.h"
#include "harness/display_png.h"
#include "imaging/exr_file.h"
#include "imaging/png_file.h"
#include "spectral/observer.h"

namespace prism::app::test {
namespace {

TEST(ReferenceDisplay, APngTakesRendersDisplayOptions) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "reference_display";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string trace =
      "reference " + std::string(PRISM_SCENES_DIR) + "/spheres_d65.json --width 24 --height 16 --spp 4 --seed 3 --ev 9";
  const std::string shown = " --white-balance A --adaptation cat02 --tonemap reinhard --display display-p3";
  Result linear = run(trace + " -o " + (dir / "linear.exr").string());
  ASSERT_EQ(linear.exitCode, 0) << linear.err;
  Result png = run(trace + shown + " -o " + (dir / "shown.png").string());
  ASSERT_EQ(png.exitCode, 0) << png.err;

  // The PNG is the EXR's tristimulus through those options' transform, pixel for pixel (before,
  // the default transform whatever was wanted: no option to ask for another).
  render::DisplaySettings display;
  display.ev100 = 9.0f;
  display.whiteBalance = "A";
  display.adaptation = Adaptation::Cat02;
  display.toneMap = render::ToneMap::Reinhard;
  display.colourSpace = "display-p3";
  const imaging::PngImage expected =
      harness::displayImage(imaging::readExr(dir / "linear.exr").image, display, observer("cie1931"), 9.0f);
  const imaging::PngImage written = imaging::readPng8(dir / "shown.png");
  ASSERT_EQ(written.width(), expected.width());
  ASSERT_EQ(written.height(), expected.height());
  for (int y = 0; y < expected.height(); ++y)
    for (int x = 0; x < expected.width(); ++x) ASSERT_EQ(written.pixel(x, y), expected.pixel(x, y)) << x << ", " << y;

  // merge writes the same PNG from the parts of a split render.
  std::string parts;
  for (int i = 0; i < 2; ++i) {
    const std::filesystem::path part = dir / ("part" + std::to_string(i) + ".exr");
    Result traced = run(trace + " --tile " + std::to_string(i) + "/2 -o " + part.string());
    ASSERT_EQ(traced.exitCode, 0) << traced.err;
    parts += " " + part.string();
  }
  Result merged = run("merge" + parts + shown + " -o " + (dir / "merged.png").string());
  ASSERT_EQ(merged.exitCode, 0) << merged.err;
  EXPECT_EQ(slurp(dir / "merged.png"), slurp(dir / "shown.png"));

  // A cluster's merge job is given them, as --KEY=VALUE, and a lamp's .csv named relative to
  // where the script was made by its absolute path: the job runs wherever it is submitted from.
  Result script = run("cluster script " + trace + shown + " --tasks 2 -o " + (dir / "cluster.png").string());
  ASSERT_EQ(script.exitCode, 0) << script.err;
  EXPECT_NE(script.out.find("prism merge " + dir.string() + "/cluster.png.parts/part-*-of-2.exr -o " + dir.string() +
                            "/cluster.png --white-balance=A --adaptation=cat02 --tonemap=reinhard --display=display-p3\n"),
            std::string::npos)
      << script.out;
  {
    std::ofstream lamp(dir / "lamp.csv");
    lamp << "wavelength_nm,value\n";
    for (int nm = 360; nm <= 830; nm += 10) lamp << nm << "," << 1.0 + nm / 1000.0 << "\n";
  }
  Result relative = run("cluster script " + trace + " --white-balance lamp.csv --tasks 2 -o " + (dir / "lamp.png").string(),
                        "cd " + dir.string() + " &&");
  ASSERT_EQ(relative.exitCode, 0) << relative.err;
  EXPECT_NE(relative.out.find(" --white-balance=" + (dir / "lamp.csv").string() + "\n"), std::string::npos)
      << relative.out;

  // An EXR holds linear tristimulus: refused in one line, before the trace, the merge or the script.
  const std::string refused = "prism: error: --tonemap reinhard: an EXR holds linear tristimulus, before the display "
                              "transform this shapes (write a .png for it)\n";
  for (const std::string& command :
       {trace + " --tonemap reinhard -o " + (dir / "x.exr").string(),
        trace + " --tonemap reinhard --tile 0/2 -o " + (dir / "x.exr").string(),
        "merge" + parts + " --tonemap reinhard -o " + (dir / "x.exr").string(),
        "cluster script " + trace + " --tonemap reinhard --tasks 2 -o " + (dir / "x.exr").string()}) {
    Result r = run(command);
    EXPECT_EQ(r.exitCode, 1) << command;
    EXPECT_EQ(r.err, refused) << command;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
  // Dither is render's GPU pass alone: the reference's PNG is encoded on the CPU, undithered.
  EXPECT_EQ(run(trace + " --dither off -o " + (dir / "x.png").string()).exitCode, 2);
}

}  // namespace
}  // namespace prism::app::test

#include "harness/colour_checker_chart.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_extension.h"
#include "imaging/png_file.h"
#include "spectral/colour_checker.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::harness {
namespace {

const char* const kIlluminants[] = {"D65", "A", "F2", "F11"};

constexpr int kPatch = 72, kGap = 10, kTitle = 34, kMargin = 16;
constexpr int kPanelWidth = 6 * kPatch + 7 * kGap;
constexpr int kPanelHeight = kTitle + 4 * kPatch + 5 * kGap;

}  // namespace

std::vector<ChartPatch> renderColourChecker(const std::string& illuminantName,
                                            const std::string& adaptation) {
  const Observer& cie = observer("cie1931");
  const RgbColourSpace& srgb = colourSpace("srgb");
  Spectrum light = illuminant(illuminantName);
  Eigen::Matrix3d adapt = Eigen::Matrix3d::Identity();
  if (adaptation != "none")
    adapt = chromaticAdaptation(adaptationFromName(adaptation), whiteTristimulus(cie, light),
                                srgb.whiteXyz());
  std::vector<ChartPatch> patches;
  for (const ColourCheckerPatch& p : colourChecker()) {
    ChartPatch out{p.name, srgb.xyzToRgb * adapt * reflectanceTristimulus(cie, p.reflectance, light)};
    Eigen::Vector3d encoded = srgb.encode(out.linearSrgb.cwiseMax(0.0).cwiseMin(1.0));
    for (int c = 0; c < 3; ++c) out.srgb8[c] = static_cast<int>(std::lround(encoded[c] * 255.0));
    patches.push_back(out);
  }
  return patches;
}

std::vector<std::vector<ChartPatch>> writeColourCheckerChart(const DemoOptions& options) {
  imaging::PngImage chart(2 * kPanelWidth + 3 * kMargin, 2 * kPanelHeight + 3 * kMargin, {40, 40, 40});
  std::vector<std::vector<ChartPatch>> all;
  for (int panel = 0; panel < 4; ++panel) {
    const char* name = kIlluminants[panel];
    std::vector<ChartPatch> patches = renderColourChecker(name, options.adaptation);
    int px = kMargin + (panel % 2) * (kPanelWidth + kMargin);
    int py = kMargin + (panel / 2) * (kPanelHeight + kMargin);
    chart.fillRect(px, py, kPanelWidth, kPanelHeight, {20, 20, 20});
    chart.drawText(px + kGap, py + 8, name, {230, 230, 230}, 3);
    const auto& layout = colourChecker();
    for (std::size_t i = 0; i < patches.size(); ++i) {
      int x = px + kGap + (layout[i].column - 1) * (kPatch + kGap);
      int y = py + kTitle + kGap + (layout[i].row - 1) * (kPatch + kGap);
      const int* v = patches[i].srgb8;
      chart.fillRect(x, y, kPatch, kPatch,
                     {static_cast<std::uint8_t>(v[0]), static_cast<std::uint8_t>(v[1]),
                      static_cast<std::uint8_t>(v[2])});
    }
    all.push_back(std::move(patches));
  }
  chart.write(options.output);
  return all;
}

void runDemo(const DemoOptions& options) {
  requireExtension(options.output, ".png", "", "chart");
  if (options.adaptation != "none" && options.adaptation != "bradford" && options.adaptation != "cat02" &&
      options.adaptation != "von-kries")
    throw Error(fmt::format("--adaptation: unknown chromatic adaptation '{}' (known: bradford, cat02, von-kries, none)",
                            options.adaptation));
  std::vector<std::vector<ChartPatch>> all = writeColourCheckerChart(options);
  if (options.json) {
    nlohmann::json json = nlohmann::json::object();
    for (std::size_t panel = 0; panel < all.size(); ++panel) {
      for (const ChartPatch& p : all[panel]) {
        json[kIlluminants[panel]].push_back(
            {{"patch", p.name},
             {"srgb8", {p.srgb8[0], p.srgb8[1], p.srgb8[2]}},
             {"linearSrgb", {p.linearSrgb.x(), p.linearSrgb.y(), p.linearSrgb.z()}}});
      }
    }
    fmt::print("{}\n", nlohmann::json{{"chart", options.output.string()},
                                      {"adaptation", options.adaptation},
                                      {"patches", json}}
                           .dump(2));
    return;
  }
  fmt::print("ColorChecker (BabelColor average), CIE 1931 2°, {}, sRGB 8-bit\n",
             options.adaptation == "none" ? std::string("not white-balanced")
                                          : "white-balanced to D65 by " + options.adaptation);
  fmt::print("{:<24}", "patch");
  for (const char* name : kIlluminants) fmt::print(" {:>13}", name);
  fmt::print("\n");
  int clipped = 0;
  for (std::size_t i = 0; i < all[0].size(); ++i) {
    fmt::print("{:<24}", all[0][i].name);
    for (const auto& patches : all) {
      const ChartPatch& p = patches[i];
      bool outside = (p.linearSrgb.array() < 0.0).any() || (p.linearSrgb.array() > 1.0).any();
      clipped += outside;
      fmt::print(" {:>3} {:>3} {:>3}{}", p.srgb8[0], p.srgb8[1], p.srgb8[2], outside ? '*' : ' ');
    }
    fmt::print("\n");
  }
  fmt::print("* outside the sRGB gamut, clipped per channel ({} of {})\n", clipped,
             4 * all[0].size());
  fmt::print("chart: {}\n", options.output.string());
}

}  // namespace prism::harness

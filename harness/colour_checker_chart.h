// `prism chart` (and a panel of `prism demo`'s gallery): the 24 ColorChecker patches under D65,
// A, F2 and F11, each lit spectrally (reflectance × SPD through CIE 1931), white-balanced to D65
// with a chromatic adaptation transform as a camera would be, then encoded as 8-bit sRGB.
// Writes the chart as a PNG and prints every patch's sRGB values.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace prism::harness {

struct ChartPatch {
  std::string name;
  Eigen::Vector3d linearSrgb;  // before clipping
  int srgb8[3] = {0, 0, 0};    // clipped to [0, 1] per channel, sRGB-encoded, rounded
};

// adaptation: "bradford" | "cat02" | "von-kries" | "none" (show the illuminant's colour cast).
std::vector<ChartPatch> renderColourChecker(const std::string& illuminantName,
                                            const std::string& adaptation);

struct DemoOptions {
  std::filesystem::path output = "out/colorchecker.png";
  std::string adaptation = "bradford";
  bool json = false;
};
// Writes the chart; the patches of the four panels, in kIlluminants order.
std::vector<std::vector<ChartPatch>> writeColourCheckerChart(const DemoOptions& options);
// Writes the chart and prints the patches (text or JSON).
void runDemo(const DemoOptions& options);

}  // namespace prism::harness

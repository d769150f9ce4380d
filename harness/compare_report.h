// `prism compare REF TEST`: how far a test image is from a reference, as a viewer would judge
// it (imaging/image_difference.h): mean, median, 95th and 99th percentile and max CIEDE2000,
// the share of pixels above a threshold, MAE on 8-bit sRGB and the relative error on linear
// values; optionally a heat map and a histogram of the per-pixel ΔE00 as PNG pictures.
#pragma once

#include <filesystem>
#include <optional>

namespace prism::harness {

struct CompareOptions {
  std::filesystem::path reference;
  std::filesystem::path test;
  std::filesystem::path heatmap;    // optional PNG
  std::filesystem::path histogram;  // optional PNG
  // CIELAB white of linear images (default: the files' display white, which must agree when both
  // record one; the one that records it, else 1).
  std::optional<double> white;
  double threshold = 1.0;           // ΔE00 above which a pixel counts as failing
  std::optional<double> scaleMax;   // ΔE00 at the top of the heat map's and histogram's scale (10)
  bool json = false;
};
void runCompare(const CompareOptions& options);

}  // namespace prism::harness

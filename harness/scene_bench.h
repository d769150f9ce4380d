// `prism bench SCENE.json`: GPU time per pass from timer queries, RGB mode beside spectral modes
// at several wavelength counts, measured side by side in one run; the linear fit
// t(n) = a·n + b of frame time against the wavelength count, spectral/RGB ratios, the GPU
// memory the spectral mode adds, and a plot of frame time against n.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/frame_settings.h"

namespace prism::harness {

struct SceneBenchOptions {
  std::filesystem::path scene;
  std::vector<int> wavelengths{4, 8, 16, 32, 64, 128, 256};
  render::FrameSettings settings;  // width, height, lookup, … in RGB mode (the mode is set per configuration)
  int frames = 100;                // timed frames per configuration (the median is reported)
  int warmup = 10;
  bool json = false;
  std::filesystem::path plot;      // .svg, optional
};
void runSceneBench(const SceneBenchOptions& options);

}  // namespace prism::harness

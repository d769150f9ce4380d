// `prism wavelengths optimise SCENE`: the optimised strategy's set for a scene (fitted with a
// progress bar, or read from the cache) and how one frame of it shows colours beside the other
// strategies' single frames: under each of the scene's lights alone, the mean and largest ΔE00
// from the 1 nm integral over the ColorChecker and over the whole training set
// (spectral/wavelength_fit.h, scene/scene_emission.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/wavelength_fit.h"

namespace prism::harness {

struct StrategyErrors {
  std::string strategy;  // e.g. "optimised", "uniform", "lights (mean of 32 single frames)"
  FitError chart;        // the 24 ColorChecker patches
  FitError training;     // every reflectance the fit trained on
};

struct LightErrors {
  std::string light;  // the scene's label of its SPD, or "background"
  std::vector<StrategyErrors> strategies;
};

struct WavelengthReport {
  FittedWavelengths set;
  std::filesystem::path cacheFile;
  std::size_t reflectances = 0;  // in the training set
  std::vector<LightErrors> lights;
};

// `settings`: its wavelengths, range and observer (the strategy is optimised whatever it says).
WavelengthReport wavelengthReport(const Scene& scene, const render::FrameSettings& settings,
                                  const RgbToSpectrumTable& table);

}  // namespace prism::harness

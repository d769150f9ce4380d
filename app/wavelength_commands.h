// `prism wavelengths optimise SCENE`: fits (or reads from the cache) the optimised strategy's
// wavelengths for a scene's lights and reports them against the other strategies' single frames
// (harness/wavelength_report.h). Writes to stdout; throws prism::Error on bad input.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/render_commands.h"

namespace prism::app {

struct WavelengthsOptimiseOptions {
  std::filesystem::path scene;
  SettingsOptions settings;        // wavelengths, range, observer (--camera)
  std::vector<std::string> sets;   // scene overrides key=value
  bool json = false;
};
void runWavelengthsOptimise(const WavelengthsOptimiseOptions& options);

}  // namespace prism::app

// `prism reference`: a scene through the CPU spectral path tracer (prism::reference), to an EXR
// of linear tristimulus (XYZ in cd/m², or raw camera RGB) or a PNG after the same display
// transform as `prism render`.
#pragma once

#include <cstdint>
#include <optional>
#include <filesystem>
#include <string>
#include <vector>

#include "reference/path_tracer.h"

namespace prism::app {

struct ReferenceOptions {
  std::filesystem::path scene;
  std::filesystem::path output;    // .exr or .png
  std::filesystem::path variance;  // optional .exr of the per-pixel variance of the mean
  std::vector<std::string> sets;   // scene overrides key=value
  int width = 640;
  int height = 360;
  int samplesPerPixel = 64;
  std::string transport = "direct";
  int maxDepth = 16;
  std::string filter = "box";
  std::string observer = "cie1931";
  std::string camera;              // a camera as the observer (overrides observer)
  std::vector<double> range;       // min, max nm
  std::string strategy = "importance";
  std::uint32_t seed = 0;
  unsigned threads = 0;
  std::optional<float> ev100;      // for the PNG and the display white (default: the scene's)
};
reference::ReferenceSettings referenceSettings(const ReferenceOptions& options);
void runReference(const ReferenceOptions& options);

}  // namespace prism::app

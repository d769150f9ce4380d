// `prism reference`: a scene through the CPU spectral path tracer (prism::reference), to an EXR
// of linear tristimulus (XYZ in cd/m², or raw camera RGB) or a PNG after the same display
// transform as `prism render`; and the helpers `prism validate` shares with it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "imaging/float_image.h"
#include "imaging/png_file.h"
#include "reference/path_tracer.h"
#include "render/frame_settings.h"
#include "scene/scene.h"

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

// Linear tristimulus (XYZ, or camera RGB for a camera observer) through the post pass's maths
// on the CPU (render::encodeForDisplay, no dither): what `prism render` would show.
imaging::PngImage displayImage(const imaging::FloatImage& tristimulus,
                               const render::FrameSettings& settings, float sceneEv100);

}  // namespace prism::app

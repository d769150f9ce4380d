// `prism reference`: a scene through the CPU spectral path tracer (prism::reference), to an EXR
// of linear tristimulus (XYZ in cd/m², or raw camera RGB) or a PNG after the same display
// transform as `prism render`. With --tile I/N or --samples A:B, one part of the render (a task
// of a Slurm array; batch/reference_part.h), which is skipped when its part file is already
// complete, so that running the array again does only what is missing.
#pragma once

#include <cstdint>
#include <optional>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "app/render_commands.h"
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
  std::optional<int> maxDepth;     // global transport only (default: ReferenceSettings')
  std::string filter = "box";
  std::string observer = "cie1931";
  std::string camera;              // a camera as the observer (overrides observer)
  std::vector<double> range;       // min, max nm
  std::string strategy = "lights";
  std::uint32_t seed = 0;
  unsigned threads = 0;
  std::optional<float> ev100;      // for the PNG and the display white (default: the scene's)
  SettingsOptions display;         // the PNG's display transform: keys for which isReferenceDisplayKey
  std::string tile;                // "I/N": rows ⌊I·height/N⌋ to ⌊(I+1)·height/N⌋ only (a part)
  std::string samples;             // "A:B": path indices A to B of every pixel only (a part)
};
reference::ReferenceSettings referenceSettings(const ReferenceOptions& options);
void runReference(const ReferenceOptions& options);

// Error naming the file unless `output` is .exr or .png and `variance` (when given) is .exr.
void checkReferenceOutputs(const std::filesystem::path& output, const std::filesystem::path& variance);

// The display keys `prism reference` and `prism merge` take for a PNG, as `prism render` does:
// white balance, adaptation, tone map and display (not dither: the PNG is encoded on the CPU,
// undithered).
bool isReferenceDisplayKey(std::string_view key);
// The display transform those keys give (the key table's parse and checks); Error naming the
// first one given when `output` is an EXR, which holds linear tristimulus.
render::DisplaySettings referenceDisplay(const SettingsOptions& display, const std::filesystem::path& output);

// A whole reference image as `prism reference` writes it (and `prism merge`, the same bytes):
// OUT.exr of tristimulus for `observerName` with the display white of `ev100` (and for a camera
// its name and `cameraToXyz`, its matrix under the scene's light), or OUT.png after `display`'s
// transform at `ev100` through that matrix; the variance EXR when `variance` is not empty. Refuses
// non-finite pixels. PRISM_CHECKs that a camera has its matrix.
void writeReferenceImage(const reference::ReferenceImage& image, const std::string& observerName, float ev100,
                         const render::DisplaySettings& display, const std::filesystem::path& output,
                         const std::filesystem::path& variance, const std::optional<Eigen::Matrix3d>& cameraToXyz);

}  // namespace prism::app

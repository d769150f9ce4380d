// `prism render`: one scene to a PNG (display-referred, after the post pass) or an EXR (linear
// tristimulus, untouched: XYZ in cd/m², or raw camera RGB for a camera observer).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/frame_settings.h"
#include "scene/scene.h"

namespace prism::app {

// The options every command that renders shares (render, bench, demo).
struct RenderSettingsOptions {
  int width = 1280;
  int height = 720;
  int wavelengths = 16;
  std::vector<double> range;  // min, max nm; empty: 360–830
  std::string strategy = "uniform";
  std::string mode = "jakob-hanika";
  std::string observer = "cie1931";
  std::string camera;  // a camera from data/cameras.csv as the observer (overrides observer)
  std::string lookup = "filtered";
  std::string gbuffer = "rgb";  // what the G-buffer keeps of a base colour: rgb or coefficients
  std::string toneMap = "aces";
  std::string display = "srgb";
  std::string whiteBalance = "none";
  std::string adaptation = "bradford";
  std::optional<float> ev100;
  int shadowMapSize = 2048;
  bool gizmos = false;  // light gizmos in the forward pass
};
render::FrameSettings frameSettings(const RenderSettingsOptions& options);

struct RenderOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  RenderSettingsOptions settings;
  int frames = 1;  // accumulated (stochastic strategies converge)
  std::vector<std::string> sets;  // scene overrides key=value
};
void runRender(const RenderOptions& options);

// Renders `frames` frames of an already loaded scene headlessly and writes `output` (.png or
// .exr); shared by `render` and `demo`.
void renderToFile(const Scene& scene, const render::FrameSettings& settings, int frames,
                  const std::filesystem::path& output, bool progress);

}  // namespace prism::app

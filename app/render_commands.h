// `prism render`: one scene to a PNG (display-referred, after the post pass) or an EXR (linear
// tristimulus, untouched: XYZ in cd/m², or raw camera RGB for a camera observer).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "render/frame_settings.h"
#include "scene/scene.h"

namespace prism::app {

// The frame settings a command line gave (render, view, bench, settings): each KEY VALUE as text,
// in the table's order (render/setting_keys.h), and --camera (an observer that must be a camera).
struct SettingsOptions {
  std::vector<std::pair<std::string, std::string>> values;
  std::string camera;
};
// The table's parse of each value over the defaults, then validate(); Error naming the key.
render::FrameSettings frameSettings(const SettingsOptions& options);

// Whether `key` shapes the display transform (white balance, adaptation, tone map, display,
// dither): what a PNG shows, nothing of an EXR's linear tristimulus.
bool isDisplayKey(std::string_view key);
// Error naming the first display key `options` give when `output` is an EXR.
void refuseDisplayOptionsOnExr(const SettingsOptions& options, const std::filesystem::path& output);

struct RenderOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  SettingsOptions settings;
  int frames = 1;  // accumulated (stochastic strategies converge)
  std::vector<std::string> sets;  // scene overrides key=value
};
void runRender(const RenderOptions& options);

// Renders `frames` frames of an already loaded scene headlessly and writes `output` (.png or
// .exr); shared by `render` and `demo`.
void renderToFile(const Scene& scene, const render::FrameSettings& settings, int frames,
                  const std::filesystem::path& output, bool progress);

}  // namespace prism::app

// Everything the viewer lets a user turn, as text: one place that names each setting, used by
// the script's `set KEY VALUE`, by the settings files (JSON) and by the UI's labels.
//
// Frame keys (render::FrameSettings): mode, wavelengths, range (MIN,MAX nm), strategy, observer
// (cie1931, cie1964 or a camera), lookup, gbuffer, tonemap, display, white-balance, adaptation,
// ev (EV100, or "scene"), shadow-map-size.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "render/frame_settings.h"
#include "scene/scene.h"

namespace prism::viewer {

// The two halves of the split view (right is used only when split), and the heat map of their
// CIEDE2000 difference.
struct ViewSettings {
  render::FrameSettings left;
  render::FrameSettings right;
  bool split = false;
  bool heatMap = false;
};

// The numbers of settings and script commands: a finite number, or a whole one within [min, max];
// Error naming `what` and the text otherwise.
double parseNumber(std::string_view what, std::string_view text);
long parseInteger(std::string_view what, std::string_view text, long min, long max);
float parseFloat(std::string_view what, std::string_view text);  // parseNumber, as a float

// Applies `key` = `value` to frame settings; false when the key is not a frame key. Error naming
// the key and what it expects when the value is bad (validate() then checks the combination).
bool applyFrameSetting(render::FrameSettings& settings, std::string_view key, std::string_view value);
// Every frame key with its value as applyFrameSetting reads it back.
std::map<std::string, std::string> frameSettingValues(const render::FrameSettings& settings);

// Settings files: {"left": {KEY: VALUE…}, "right": {…}, "split": bool, "heat_map": bool,
// "camera": {"position", "target", "up", "fov_deg"}}, written atomically. Loading checks all of
// it first (Error "FILE: /left/mode: …") and changes nothing on failure.
void saveViewSettings(const std::filesystem::path& path, const ViewSettings& view, const Camera& camera);
void loadViewSettings(const std::filesystem::path& path, ViewSettings& view, Camera& camera);

}  // namespace prism::viewer

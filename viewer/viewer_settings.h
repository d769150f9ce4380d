// What the viewer lets a user set as text beyond one frame's settings: the split view's two
// halves, and the settings files. The frame keys themselves (names, parsing, printing) are
// render/setting_keys.h's table, shared with the command line.
#pragma once

#include <filesystem>
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

// The viewer's first view: `initial` on the left, and on the right RGB mode under CIE 1931 (RGB
// mode's own observer: its colour spaces are defined on it).
ViewSettings initialView(const render::FrameSettings& initial);

// Error naming `png` when a PNG of the window would hold two display spaces: the split views
// encoded for different ones. A PNG names one (its cICP chunk), which compare and colour-managed
// viewers decode all of it by; the window's was tagged as the left view's.
void requireOneDisplaySpace(const ViewSettings& view, const std::filesystem::path& png);

// The view's keys of the script's `set KEY VALUE`: a frame key (the left view, or the only one),
// right.KEY (the right view), split and heat-map (on or off). Returns false when `key` is none of
// these; Error naming the key and what it expects when the value is bad (validate() then checks
// the combination).
bool applyViewSetting(ViewSettings& view, std::string_view key, std::string_view value);

// Settings files: {"left": {KEY: VALUE…}, "right": {…}, "split": bool, "heat_map": bool,
// "camera": {"position", "target", "up", "fov_deg"}}, written atomically. Loading checks all of
// it first (Error "FILE: /left/mode: …") and changes nothing on failure. The views' width and
// height are the window's: not written, and a file's (older files hold them) not taken.
void saveViewSettings(const std::filesystem::path& path, const ViewSettings& view, const Camera& camera);
void loadViewSettings(const std::filesystem::path& path, ViewSettings& view, Camera& camera);

}  // namespace prism::viewer

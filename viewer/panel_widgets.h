// ImGui controls that several panels share: a combo over strings, one over a frame key's values
// (its names, choices and help from render/setting_keys.h, the same text as the command line and
// the script), the frame settings of one half of the split (the spectral and split panels), and
// the names they offer.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "render/frame_settings.h"

namespace prism::viewer {

bool stringCombo(const char* label, std::string& value, const std::vector<std::string>& choices);
// The values of the frame key `key` (a Choice or Switch key), labelled with its name; true when
// the user picked one.
bool settingCombo(render::FrameSettings& s, std::string_view key);

// Mode, wavelengths, range, strategy and observer of one view; `id` keeps the two views' apart.
bool frameSettingsControls(render::FrameSettings& s, const char* id, const std::vector<std::string>& observers);

// The named illuminants (the parametric families, "blackbody:<K>", have their own controls).
std::vector<std::string> illuminantChoices();
// The CIE observers, then the cameras.
std::vector<std::string> observerChoices();

}  // namespace prism::viewer

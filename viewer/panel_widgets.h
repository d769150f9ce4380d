// ImGui controls that several panels share: a combo over named values, one over strings, the
// frame settings of one half of the split (the spectral and split panels), and the names they
// offer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "render/frame_settings.h"

namespace prism::viewer {

// True when the user picked a value (then in `value`).
template <typename T>
bool combo(const char* label, T& value, const std::vector<std::pair<T, std::string>>& choices) {
  std::string current;
  for (const auto& [v, name] : choices) if (v == value) current = name;
  bool changed = false;
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (const auto& [v, name] : choices) {
      if (ImGui::Selectable(name.c_str(), v == value)) {
        value = v;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool stringCombo(const char* label, std::string& value, const std::vector<std::string>& choices);

// Mode, wavelengths, range, strategy and observer of one view; `id` keeps the two views' apart.
bool frameSettingsControls(render::FrameSettings& s, const char* id, const std::vector<std::string>& observers);

// The named illuminants (the parametric families, "blackbody:<K>", have their own controls).
std::vector<std::string> illuminantChoices();
// The CIE observers, then the cameras.
std::vector<std::string> observerChoices();

}  // namespace prism::viewer

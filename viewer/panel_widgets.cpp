#include "viewer/panel_widgets.h"

#include <algorithm>

#include "core/error.h"
#include "render/setting_keys.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::viewer {

bool stringCombo(const char* label, std::string& value, const std::vector<std::string>& choices) {
  bool changed = false;
  if (ImGui::BeginCombo(label, value.c_str())) {
    for (const std::string& c : choices) {
      if (ImGui::Selectable(c.c_str(), c == value)) {
        value = c;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool settingCombo(render::FrameSettings& s, std::string_view key) {
  const render::SettingKey* k = render::findFrameSettingKey(key);
  PRISM_CHECK(k && !k->choices.empty());
  std::string value = k->print(s);
  bool changed = stringCombo(k->name.c_str(), value, k->choices);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", k->help.c_str());
  if (changed) k->parse(s, value);
  return changed;
}

bool frameSettingsControls(render::FrameSettings& s, const char* id, const std::vector<std::string>& observers) {
  ImGui::PushID(id);
  bool changed = settingCombo(s, "mode");
  int count = s.sampling.count;
  const int maxCount = s.sampling.strategy == SamplingStrategy::Optimised ? kMaxFittedWavelengths : 256;
  if (ImGui::SliderInt("wavelengths", &count, 4, maxCount)) {
    s.sampling.count = std::max(4, count / 4 * 4);
    changed = true;
  }
  float range[2] = {static_cast<float>(s.sampling.minNm), static_cast<float>(s.sampling.maxNm)};
  if (ImGui::SliderFloat2("range nm", range, 360.0f, 830.0f, "%.0f")) {
    s.sampling.minNm = std::clamp<double>(range[0], 360.0, 829.0);
    s.sampling.maxNm = std::clamp<double>(range[1], s.sampling.minNm + 1.0, 830.0);
    changed = true;
  }
  if (settingCombo(s, "strategy")) {
    if (s.sampling.strategy == SamplingStrategy::Optimised)  // a fitted set has at most 64
      s.sampling.count = std::min(s.sampling.count, kMaxFittedWavelengths);
    changed = true;
  }
  changed |= stringCombo("observer", s.observer, observers);
  ImGui::PopID();
  return changed;
}

std::vector<std::string> illuminantChoices() {
  std::vector<std::string> names;
  for (const IlluminantInfo& info : listIlluminants()) {
    if (info.name.find('<') == std::string::npos) names.push_back(info.name);
  }
  return names;
}

std::vector<std::string> observerChoices() {
  std::vector<std::string> names = {"cie1931", "cie1964"};
  for (const std::string& c : listCameras()) names.push_back(c);
  return names;
}

}  // namespace prism::viewer

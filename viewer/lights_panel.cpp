// The lights panel: for each light its SPD (a named illuminant, a blackbody, an LED or a CSV
// file), its intensity, whether it casts shadows, its position (point and spot lights) and,
// unless it is a point light, its direction as azimuth and elevation.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "viewer/light_spectrum.h"
#include "viewer/panel_widgets.h"
#include "viewer/panels.h"

namespace prism::viewer {
namespace {

const char* typeName(LightType type) {
  return type == LightType::Directional ? "directional" : type == LightType::Point ? "point" : "spot";
}

class LightsPanel final : public Panel {
 public:
  const char* title() const override { return "Lights"; }

  void draw(PanelContext& context) override {
    for (std::size_t i = 0; i < context.scene.lights.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));
      lightControls(context, i);
      ImGui::Separator();
      ImGui::PopID();
    }
  }

 private:
  void lightControls(PanelContext& context, std::size_t i) {
    Light& light = context.scene.lights[i];
    bool& changed = context.changes.scene;
    ImGui::Text("light %zu (%s): %s", i, typeName(light.type), light.spdLabel.c_str());
    std::string choice = light.spdLabel;
    if (stringCombo("SPD", choice, mIlluminants)) {
      runAction(context, [&] {
        setLightSpd(light, choice);
        changed = true;
      });
    }
    if (ImGui::SliderFloat("blackbody K", &mBlackbodyK, 1000.0f, 12000.0f, "%.0f K")) {
      runAction(context, [&] {
        setLightSpd(light, fmt::format("blackbody:{:.0f}", mBlackbodyK));
        changed = true;
      });
    }
    float led[2] = {mLedPeakNm, mLedWidthNm};
    if (ImGui::SliderFloat2("LED peak, width nm", led, 380.0f, 700.0f, "%.0f")) {
      mLedPeakNm = led[0];
      mLedWidthNm = std::clamp(led[1], 5.0f, 100.0f);
      runAction(context, [&] {
        setLightSpd(light, fmt::format("led:{:.0f}:{:.0f}", mLedPeakNm, mLedWidthNm));
        changed = true;
      });
    }
    ImGui::InputText("CSV file", mCsvPath.data(), mCsvPath.size());
    ImGui::SameLine();
    if (ImGui::Button("load")) {
      runAction(context, [&] {
        setLightSpdFromCsv(light, mCsvPath.data());
        changed = true;
      });
    }
    if (ImGui::SliderFloat("intensity", &light.intensity, 1.0f, 200000.0f, "%.0f", ImGuiSliderFlags_Logarithmic)) {
      changed = true;
    }
    changed |= ImGui::Checkbox("casts shadows", &light.castsShadows);
    if (light.type != LightType::Directional) {
      changed |= ImGui::DragFloat3("position m", &light.position.x, 0.05f, -1000.0f, 1000.0f, "%.2f");
    }
    if (light.type != LightType::Point) {
      glm::vec3 d = glm::normalize(light.direction);
      float azimuth = std::atan2(d.x, d.z) / kDegrees, elevation = std::asin(-d.y) / kDegrees;
      bool turned = ImGui::SliderFloat("azimuth", &azimuth, -180.0f, 180.0f, "%.0f°");
      turned |= ImGui::SliderFloat("elevation", &elevation, -89.0f, 89.0f, "%.0f°");
      if (turned) {
        float a = azimuth * kDegrees, e = elevation * kDegrees;
        light.direction = glm::vec3(std::cos(e) * std::sin(a), -std::sin(e), std::cos(e) * std::cos(a));
        changed = true;
      }
    }
  }

  std::vector<std::string> mIlluminants = illuminantChoices();
  // One set for all the lights: what the user last typed or dragged.
  float mBlackbodyK = 3000.0f, mLedPeakNm = 450.0f, mLedWidthNm = 20.0f;
  std::array<char, 512> mCsvPath{};
};

}  // namespace

std::unique_ptr<Panel> makeLightsPanel() { return std::make_unique<LightsPanel>(); }

}  // namespace prism::viewer

// The nebula panel (techniques/nebula): method, basis size, steps, filters, intensity, the
// medium, the density's noise and the stars. Sees only the PanelContext. Edits that make the
// pass precompute again (anything of the model: about a second at 64³) apply when a slider is
// released, not while it is dragged.
#include <imgui.h>

#include <fmt/format.h>

#include "techniques/nebula/nebula_section.h"
#include "techniques/nebula/viewer/nebula_viewer.h"
#include "viewer/panel_widgets.h"

namespace prism::viewer {
namespace {

// A slider whose edit counts once released.
bool releasedFloat(const char* label, double& value, float lo, float hi, const char* format, bool logarithmic = false) {
  float v = static_cast<float>(value);
  ImGui::SliderFloat(label, &v, lo, hi, format, logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
  value = v;
  return ImGui::IsItemDeactivatedAfterEdit();
}

bool noiseControls(nebula::NoiseParameters& p) {
  bool changed = false;
  ImGui::SliderInt("resolution", &p.resolution, 8, 256);
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SliderInt("octaves", &p.octaves, 1, 8);
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  changed |= releasedFloat("frequency", p.frequency, 0.5f, 12.0f, "%.2f");
  changed |= releasedFloat("amplitude", p.amplitude, 0.0f, 4.0f, "%.2f");
  changed |= releasedFloat("gain", p.gain, 0.0f, 1.0f, "%.2f");
  changed |= releasedFloat("bias", p.bias, -1.0f, 1.0f, "%.2f");
  int seed = static_cast<int>(p.seed);
  if (ImGui::InputInt("seed", &seed) && seed >= 0) {
    p.seed = static_cast<std::uint64_t>(seed);
    changed = true;
  }
  return changed;
}

bool starControls(std::vector<nebula::NebulaStar>& stars) {
  bool changed = false;
  for (std::size_t i = 0; i < stars.size(); ++i) {
    nebula::NebulaStar& s = stars[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::TextUnformatted(fmt::format("star {}", i).c_str());
    glm::vec3 p(s.position);
    ImGui::DragFloat3("position", &p.x, 0.01f, -2.0f, 3.0f, "%.2f");
    s.position = glm::dvec3(p);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    changed |= releasedFloat("temperature K", s.temperatureK, static_cast<float>(nebula::kMinStarTemperatureK),
                             static_cast<float>(nebula::kMaxStarTemperatureK), "%.0f", true);
    changed |= releasedFloat("luminosity", s.luminosity, 0.0f, 10.0f, "%.2f");
    bool remove = ImGui::Button("remove");
    ImGui::PopID();
    if (remove) {
      stars.erase(stars.begin() + static_cast<std::ptrdiff_t>(i));
      return true;
    }
  }
  if (ImGui::Button("add star")) {
    stars.push_back({glm::dvec3(0.5), 10000.0, 1.0});
    changed = true;
  }
  return changed;
}

class NebulaPanel final : public Panel {
 public:
  const char* title() const override { return "Nebula"; }
  bool applies(const Scene& scene) const override { return scene.techniques.has(nebula::NebulaSection::kKey); }

  void draw(PanelContext& context) override {
    nebula::NebulaSection& s = *context.scene.techniques.find<nebula::NebulaSection>();
    bool changed = false;
    std::string method = nebula::methodName(s.method);
    if (stringCombo("method", method, {"projection", "light-density", "reference"})) {
      s.method = nebula::methodFromName(method);
      changed = true;
    }
    ImGui::SliderInt("basis size", &s.basis, 1, 8);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SliderInt("steps", &s.steps, 10, 400);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    changed |= stringCombo("filters", s.model.filters, {"hubble", "cie1931"});
    changed |= ImGui::SliderFloat("intensity", &s.intensity, 1e-3f, 1e4f, "%.3g", ImGuiSliderFlags_Logarithmic);
    changed |= releasedFloat("extinction", s.model.extinction, 0.0f, 20.0f, "%.2f");
    changed |= releasedFloat("scattering", s.model.scattering, 0.0f, 10.0f, "%.2f");
    changed |= releasedFloat("emission", s.model.emission, 0.0f, 0.02f, "%.4f");
    if (s.source.noise && ImGui::TreeNode("density (noise)")) {
      if (noiseControls(*s.source.noise)) {
        s.regenerateDensity();
        changed = true;
      }
      ImGui::TreePop();
    }
    if (ImGui::TreeNode("stars")) {
      changed |= starControls(s.model.stars);
      ImGui::TreePop();
    }
    if (changed) context.changes.scene = true;
  }
};

}  // namespace

std::unique_ptr<Panel> makeNebulaPanel() { return std::make_unique<NebulaPanel>(); }

}  // namespace prism::viewer

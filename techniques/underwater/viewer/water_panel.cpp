// The water panel (techniques/underwater): the Jerlov water type and its data set, the camera's
// depth, the multipliers of each coefficient and whether lamps scatter into the view. Sees only
// the PanelContext.
#include <imgui.h>

#include "core/error.h"
#include "techniques/underwater/jerlov_water.h"
#include "techniques/underwater/water_section.h"
#include "viewer/panel_widgets.h"
#include "techniques/underwater/viewer/water_viewer.h"

namespace prism::viewer {
namespace {

class WaterPanel final : public Panel {
 public:
  const char* title() const override { return "Water"; }
  bool applies(const Scene& scene) const override { return scene.techniques.has(underwater::WaterSection::kKey); }

  void draw(PanelContext& context) override {
    underwater::WaterSection& w = *context.scene.techniques.find<underwater::WaterSection>();
    if (mTypesOf != w.dataset) {  // read from data/ when the data set changes, not every frame
      mTypes = underwater::listJerlovTypes(underwater::jerlovDatasetFromName(w.dataset));
      mTypesOf = w.dataset;
    }
    bool changed = stringCombo("type", w.type, mTypes);
    changed |= stringCombo("data set", w.dataset, {"jerlov", "williamson2022"});
    changed |= ImGui::SliderFloat("camera depth m", &w.depthM, 0.0f, 60.0f, "%.1f");
    changed |= ImGui::SliderFloat("scattering x", &w.scatteringScale, 0.0f, 4.0f);
    changed |= ImGui::SliderFloat("absorption x", &w.absorptionScale, 0.0f, 4.0f);
    changed |= ImGui::SliderFloat("Kd x", &w.kdScale, 0.0f, 4.0f);
    changed |= ImGui::Checkbox("lamps scatter into the view", &w.lampScattering);
    if (changed) apply(context);
  }

 private:
  static void apply(PanelContext& context) {
    underwater::WaterSection& w = *context.scene.techniques.find<underwater::WaterSection>();
    try {
      w.resolve();
    } catch (const Error& e) {  // a type the other data set lacks: back to its first
      w.type = underwater::listJerlovTypes(underwater::jerlovDatasetFromName(w.dataset)).front();
      w.resolve();
      context.actionError = e.what();
    }
    context.changes.scene = true;
  }

  std::vector<std::string> mTypes;  // of the data set mTypesOf
  std::string mTypesOf;
};

}  // namespace

std::unique_ptr<Panel> makeWaterPanel() { return std::make_unique<WaterPanel>(); }

}  // namespace prism::viewer

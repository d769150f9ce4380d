// The display panel: tone map, exposure (the scene camera's or EV100), white balance, its
// adaptation, the display colour space and dither. One display for both halves of the split:
// the right view follows the left.
#include <imgui.h>

#include <optional>

#include "viewer/panel_widgets.h"
#include "viewer/panels.h"

namespace prism::viewer {
namespace {

class DisplayPanel final : public Panel {
 public:
  const char* title() const override { return "Display"; }

  void draw(PanelContext& context) override {
    render::FrameSettings& s = context.view.left;
    bool& changed = context.changes.settings;
    render::DisplaySettings& d = s.display;
    changed |= settingCombo(s, "tonemap");
    bool sceneEv = !d.ev100.has_value();
    if (ImGui::Checkbox("the scene camera's exposure", &sceneEv)) {
      d.ev100 = sceneEv ? std::nullopt : std::optional<float>(context.camera.camera().ev100);
      changed = true;
    }
    if (d.ev100) changed |= ImGui::SliderFloat("ev", &*d.ev100, -5.0f, 20.0f, "%.1f");
    changed |= stringCombo("white-balance", d.whiteBalance, mBalances);
    changed |= settingCombo(s, "adaptation");
    changed |= settingCombo(s, "display");
    changed |= settingCombo(s, "dither");
    if (changed) context.view.right.display = d;  // any settings change this frame, the other panels' too
  }

 private:
  static std::vector<std::string> balances() {
    std::vector<std::string> names{"none"};
    for (std::string& name : illuminantChoices()) names.push_back(std::move(name));
    return names;
  }

  std::vector<std::string> mBalances = balances();
};

}  // namespace

std::unique_ptr<Panel> makeDisplayPanel() { return std::make_unique<DisplayPanel>(); }

}  // namespace prism::viewer

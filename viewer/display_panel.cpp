// The display panel: tone map, exposure (the scene camera's or EV100), white balance and display
// colour space. One display for both halves of the split: the right view follows the left.
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
    changed |= combo<render::ToneMap>("tone map", s.toneMap, {{render::ToneMap::None, "none"},
                                                              {render::ToneMap::Reinhard, "reinhard"},
                                                              {render::ToneMap::Aces, "aces"}});
    bool sceneEv = !s.ev100.has_value();
    if (ImGui::Checkbox("the scene camera's exposure", &sceneEv)) {
      s.ev100 = sceneEv ? std::nullopt : std::optional<float>(context.camera.camera().ev100);
      changed = true;
    }
    if (s.ev100) changed |= ImGui::SliderFloat("EV100", &*s.ev100, -5.0f, 20.0f, "%.1f");
    changed |= stringCombo("white balance", s.whiteBalance, mBalances);
    changed |= stringCombo("display", s.display, {"srgb", "display-p3", "rec2020"});
    if (changed) {  // any settings change this frame, the other panels' too
      render::FrameSettings& right = context.view.right;
      right.toneMap = s.toneMap;
      right.ev100 = s.ev100;
      right.whiteBalance = s.whiteBalance;
      right.display = s.display;
    }
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

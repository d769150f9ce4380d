// The A/B split panel: the split on or off, the right view's spectral settings, and the CIEDE2000
// heat map of the two views' difference with its statistics (viewer/compositor.h).
#include <imgui.h>

#include <cstdint>

#include "viewer/compositor.h"
#include "viewer/panel_widgets.h"
#include "viewer/panels.h"

namespace prism::viewer {
namespace {

class SplitPanel final : public Panel {
 public:
  const char* title() const override { return "A/B split"; }
  bool openAtStart() const override { return true; }

  void draw(PanelContext& context) override {
    ViewSettings& view = context.view;
    context.changes.settings |= ImGui::Checkbox("split: left | right", &view.split);
    if (!view.split) return;
    context.changes.settings |= frameSettingsControls(view.right, "right", mObservers);
    ImGui::Checkbox("CIEDE2000 heat map", &view.heatMap);
    const gpu::Texture2D& heat = context.views.heatMap();
    if (view.heatMap && heat.id() != 0) {
      const imaging::DifferenceStats& stats = context.views.heatMapStats();
      ImGui::Text("dE00 mean %.2f  p95 %.2f  max %.1f", stats.meanDeltaE, stats.p95DeltaE, stats.maxDeltaE);
      float w = ImGui::GetContentRegionAvail().x;
      float h = w * static_cast<float>(heat.height()) / static_cast<float>(heat.width());
      ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(heat.id())), ImVec2(w, h));
    }
  }

 private:
  std::vector<std::string> mObservers = observerChoices();
};

}  // namespace

std::unique_ptr<Panel> makeSplitPanel() { return std::make_unique<SplitPanel>(); }

}  // namespace prism::viewer

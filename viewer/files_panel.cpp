// The files panel: a screenshot of the window (or the left view's EXR), the viewer's settings
// saved and loaded (viewer_settings.h), the shaders reloaded. Its actions are the viewer's own.
#include <imgui.h>

#include <array>
#include <cstdio>

#include "viewer/panels.h"
#include "viewer/viewer_loop.h"

namespace prism::viewer {
namespace {

class FilesPanel final : public Panel {
 public:
  explicit FilesPanel(Viewer& viewer) : mViewer(viewer) {
    std::snprintf(mScreenshotPath.data(), mScreenshotPath.size(), "%s", "prism_screenshot.png");
    std::snprintf(mSettingsPath.data(), mSettingsPath.size(), "%s", "prism_view_settings.json");
  }

  const char* title() const override { return "Files"; }

  void draw(PanelContext& context) override {
    ImGui::InputText("screenshot", mScreenshotPath.data(), mScreenshotPath.size());
    ImGui::SameLine();
    if (ImGui::Button("save##shot")) runAction(context, [&] { mViewer.screenshot(mScreenshotPath.data(), false); });
    ImGui::InputText("settings", mSettingsPath.data(), mSettingsPath.size());
    if (ImGui::Button("save settings")) {
      runAction(context, [&] { mViewer.saveSettings(mSettingsPath.data()); });
    }
    ImGui::SameLine();
    if (ImGui::Button("load settings")) runAction(context, [&] { mViewer.loadSettings(mSettingsPath.data()); });
    if (ImGui::Button("reload shaders")) runAction(context, [&] { mViewer.reloadShaders(); });
  }

 private:
  Viewer& mViewer;
  std::array<char, 512> mScreenshotPath{}, mSettingsPath{};
};

}  // namespace

std::unique_ptr<Panel> makeFilesPanel(Viewer& viewer) { return std::make_unique<FilesPanel>(viewer); }

}  // namespace prism::viewer

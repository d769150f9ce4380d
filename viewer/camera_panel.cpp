// The camera panel: field of view, reset, and a reminder of the mouse and keys (viewer_loop.cpp).
#include <imgui.h>

#include "viewer/panels.h"

namespace prism::viewer {
namespace {

class CameraPanel final : public Panel {
 public:
  const char* title() const override { return "Camera"; }
  bool openAtStart() const override { return true; }

  void draw(PanelContext& context) override {
    float fov = context.camera.camera().verticalFovDeg;
    if (ImGui::SliderFloat("field of view", &fov, kMinFieldOfViewDeg, kMaxFieldOfViewDeg, "%.0f°")) {
      context.camera.setFieldOfView(fov);
      context.changes.camera = true;
    }
    if (ImGui::Button("reset (R)")) {
      context.camera.reset();
      context.changes.camera = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("drag: orbit, right: look, middle: pan, wheel: dolly, WASD QE: fly");
  }
};

}  // namespace

std::unique_ptr<Panel> makeCameraPanel() { return std::make_unique<CameraPanel>(); }

}  // namespace prism::viewer

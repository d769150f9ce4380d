// The interface is a column of panels in one window, each a collapsing header over one concern.
// A panel sees the viewer only through PanelContext, so a technique's panel (water, sky) is a
// unit of its own that can move beside its technique and be registered there.
#pragma once

#include <exception>
#include <string>

#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "viewer/camera_controller.h"
#include "viewer/changes.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {

class Compositor;

// What a panel may read and edit during one frame's interface. An edit records its kind in
// `changes` for the renderers to take next frame.
struct PanelContext {
  Scene& scene;                     // edited in place
  const RgbToSpectrumTable& table;  // the scene colour space's
  ViewSettings& view;
  CameraController& camera;
  const Compositor& views;   // what was rendered: the frame's wavelengths, the heat map
  Changes& changes;          // since the renderers last took them, this frame's panels so far included
  std::string& actionError;  // shown under the frame time until the next action succeeds or dismissed
};

class Panel {
 public:
  virtual ~Panel() = default;
  virtual const char* title() const = 0;  // its header's label, also its ImGui id
  virtual bool openAtStart() const { return false; }
  // Whether the scene has what the panel edits (the water panel needs water); otherwise not shown.
  virtual bool applies(const Scene&) const { return true; }
  // The controls under the header, drawn when it is open.
  virtual void draw(PanelContext& context) = 0;
};

// An action from the interface: its error stays on screen until the next action or dismissed.
template <typename F>
void runAction(PanelContext& context, F&& action) {
  try {
    action();
    context.actionError.clear();
  } catch (const std::exception& e) {
    context.actionError = e.what();
  }
}

}  // namespace prism::viewer

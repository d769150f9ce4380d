// runViewer: the window, the viewer's loop over it (viewer_loop.h), and a person or the script
// (script.h) to drive it.
#include "viewer/viewer.h"

#include "gpu/window_context.h"
#include "viewer/script.h"
#include "viewer/viewer_loop.h"

namespace prism::viewer {

int runViewer(Scene& scene, const RgbToSpectrumTable& table, const render::FrameSettings& initial,
              const ViewerOptions& options) {
  gpu::WindowDesc desc;
  desc.width = options.width;
  desc.height = options.height;
  desc.title = "Prism — " + scene.file.filename().string();
  desc.vsync = !options.script;
  gpu::WindowContext window(desc);
  Viewer viewer(window, scene, table, initial);
  return options.script ? runScript(viewer, *options.script) : viewer.interactive();
}

}  // namespace prism::viewer

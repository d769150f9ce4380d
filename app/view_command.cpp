#include "app/view_command.h"

#include <optional>
#include <utility>

#include <fmt/format.h>

#include "core/error.h"
#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "render/frame_data.h"
#include "scene/scene_loader.h"
#include "viewer/viewer.h"

namespace prism::app {

int runView(const ViewOptions& options) {
  // The script first: a bad line or a missing file is reported before the scene loads or a window opens.
  std::optional<viewer::Script> script;
  if (!options.script.empty()) script = viewer::loadScript(options.script);
  Scene scene = loadScene(options.scene, options.sets);
  render::FrameSettings settings = frameSettings(options.settings);
  for (const auto& [name, side] : {std::pair{"--width", settings.width}, std::pair{"--height", settings.height}})
    if (side < viewer::kMinWindowSide || side > viewer::kMaxWindowSide)
      throw Error(fmt::format("{} {}: the viewer's window is {}–{} pixels a side", name, side, viewer::kMinWindowSide,
                              viewer::kMaxWindowSide));
  render::requireLightCount(scene);  // the renderer's own checks, before the work ahead of them
  render::requireTechniquesShow(scene, settings);
  // The script rehearsed on the state the viewer starts from, before the table and the techniques'
  // precomputation (a nebula's density: seconds): `set nebula.steps 0` failed after them. The run
  // rehearses it again on the viewer's own state.
  if (script) viewer::rehearseScript(*script, viewer::initialView(settings), viewer::CameraController(scene.camera), scene);
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  harness::precomputeTechniques(scene);
  viewer::ViewerOptions v;
  v.width = settings.width;
  v.height = settings.height;
  v.script = std::move(script);
  return viewer::runViewer(scene, table, settings, v);
}

}  // namespace prism::app

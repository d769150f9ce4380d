#include "app/view_command.h"

#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "scene/scene_loader.h"
#include "viewer/viewer.h"

namespace prism::app {

int runView(const ViewOptions& options) {
  Scene scene = loadScene(options.scene, options.sets);
  render::FrameSettings settings = frameSettings(options.settings);
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  harness::precomputeTechniques(scene);
  viewer::ViewerOptions v;
  v.width = settings.width;
  v.height = settings.height;
  v.script = options.script;
  return viewer::runViewer(scene, table, settings, v);
}

}  // namespace prism::app

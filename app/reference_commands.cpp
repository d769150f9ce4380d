#include "app/reference_commands.h"

#include <fmt/format.h>

#include "harness/display_png.h"
#include "harness/progress_bar.h"
#include "harness/upsampling_table.h"
#include "imaging/exr_file.h"
#include "render/display_transform.h"
#include "scene/scene_loader.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "spectral/observer.h"

namespace prism::app {

reference::ReferenceSettings referenceSettings(const ReferenceOptions& o) {
  reference::ReferenceSettings s;
  s.width = o.width;
  s.height = o.height;
  s.samplesPerPixel = o.samplesPerPixel;
  s.transport = reference::lightTransportFromName(o.transport);
  s.maxDepth = o.maxDepth;
  s.filter = reference::pixelFilterFromName(o.filter);
  s.observer = o.camera.empty() ? o.observer : o.camera;
  if (!o.camera.empty() && !observer(o.camera).isCamera) {
    throw Error(fmt::format("--camera: \"{}\" is not a camera (see `prism colour list cameras`)", o.camera));
  }
  if (!o.range.empty()) {
    if (o.range.size() != 2) throw Error("--range: expected MIN,MAX in nm");
    s.wavelengths.minNm = o.range[0];
    s.wavelengths.maxNm = o.range[1];
  }
  s.wavelengths.strategy = samplingStrategyFromName(o.strategy);
  s.seed = o.seed;
  s.threads = o.threads;
  reference::validate(s);
  return s;
}

void runReference(const ReferenceOptions& o) {
  std::string extension = o.output.extension().string();
  if (extension != ".png" && extension != ".exr") {
    throw Error(fmt::format("{}: the output must be a .png or an .exr file", o.output.string()));
  }
  if (!o.variance.empty() && o.variance.extension() != ".exr") {
    throw Error(fmt::format("{}: the variance image must be an .exr file", o.variance.string()));
  }
  Scene scene = loadScene(o.scene, o.sets);
  reference::ReferenceSettings settings = referenceSettings(o);
  requireWritable(o.output);
  if (!o.variance.empty()) requireWritable(o.variance);
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  harness::ProgressBar bar("tracing " + o.output.filename().string());
  reference::ReferenceImage image = reference::renderReference(
      scene, table, settings, [&](std::size_t done, std::size_t total) { bar.update(done, total); });

  const bool camera = observer(settings.observer).isCamera;
  const float ev100 = o.ev100.value_or(scene.camera.ev100);
  imaging::ExrWriteOptions exr{camera ? imaging::ColourMeaning::CameraRgb : imaging::ColourMeaning::Xyz,
                               imaging::ExrPrecision::Float, imaging::ExrChannelNames::FromColour,
                               render::displayWhiteLuminance(ev100)};
  imaging::requireFiniteOutput(image.tristimulus, o.output.string());
  if (extension == ".exr") {
    imaging::writeExr(o.output, image.tristimulus, exr);
  } else {
    render::DisplaySettings display;
    display.ev100 = ev100;
    harness::displayImage(image.tristimulus, display, observer(settings.observer), ev100).write(o.output);
  }
  // The variance is in squared units and no colour: not something compare should take for one.
  if (!o.variance.empty()) imaging::writeExr(o.variance, image.variance, {.colour = imaging::ColourMeaning::OtherRgb});
  fmt::print("wrote {} ({}x{}, {} paths per pixel, {} lighting)\n", o.output.string(), settings.width,
             settings.height, settings.samplesPerPixel, o.transport);
}

}  // namespace prism::app

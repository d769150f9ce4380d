#include "app/render_commands.h"

#include <fmt/format.h>

#include "gpu/headless_context.h"
#include "harness/display_png.h"
#include "harness/optimised_wavelengths.h"
#include "harness/progress_bar.h"
#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "imaging/exr_file.h"
#include "render/display_transform.h"
#include "render/renderer.h"
#include "render/setting_keys.h"
#include "scene/scene_loader.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "spectral/observer.h"

namespace prism::app {

render::FrameSettings frameSettings(const SettingsOptions& o) {
  render::FrameSettings s;
  for (const auto& [key, value] : o.values) {
    if (!render::applyFrameSetting(s, key, value)) throw Error(fmt::format("unknown setting \"{}\"", key));
  }
  if (!o.camera.empty()) {
    if (!observer(o.camera).isCamera) {
      throw Error(fmt::format("--camera: \"{}\" is not a camera (see `prism colour list cameras`)", o.camera));
    }
    s.observer = o.camera;
  }
  render::validate(s);
  return s;
}

void renderToFile(const Scene& scene, const render::FrameSettings& settings, int frames,
                  const std::filesystem::path& output, bool progress) {
  std::string extension = lowercaseExtension(output);
  if (extension != ".png" && extension != ".exr") {
    throw Error(fmt::format("{}: the output must be a .png or an .exr file", output.string()));
  }
  if (frames < 1) throw Error("--frames: must be at least 1");
  requireWritable(output);
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  harness::fitOptimisedWavelengths(scene, settings, table);
  harness::precomputeTechniques(scene);
  gpu::HeadlessContext context;
  render::Renderer renderer(scene, table, settings);
  std::optional<harness::ProgressBar> bar;
  if (progress && frames > 1) bar.emplace("rendering " + output.filename().string());
  for (int f = 0; f < frames; ++f) {
    renderer.renderFrame();
    if (bar) bar->update(static_cast<std::size_t>(f + 1), static_cast<std::size_t>(frames));
  }
  imaging::FloatImage image(settings.width, settings.height, 3);
  image.pixels = renderer.readMeanTristimulus();
  imaging::requireFiniteOutput(image, output.string());
  if (extension == ".png") {
    harness::displayPng(renderer).write(output);
    return;
  }
  bool camera = settings.mode != render::RenderMode::Rgb && observer(settings.observer).isCamera;
  imaging::writeExr(output, image,
                    {camera ? imaging::ColourMeaning::CameraRgb : imaging::ColourMeaning::Xyz,
                     imaging::ExrPrecision::Float, imaging::ExrChannelNames::FromColour,
                     render::displayWhiteLuminance(settings.display.ev100.value_or(scene.camera.ev100))});
}

void runRender(const RenderOptions& options) {
  Scene scene = loadScene(options.scene, options.sets);
  render::FrameSettings settings = frameSettings(options.settings);
  renderToFile(scene, settings, options.frames, options.output, true);
  fmt::print("wrote {} ({}x{}, {} mode, {} frame{})\n", options.output.string(), settings.width,
             settings.height, render::renderModeName(settings.mode), options.frames,
             options.frames == 1 ? "" : "s");
}

}  // namespace prism::app

#include "app/render_commands.h"

#include <fmt/format.h>

#include "app/camera_option.h"
#include "gpu/headless_context.h"
#include "harness/display_png.h"
#include "harness/optimised_wavelengths.h"
#include "harness/progress_bar.h"
#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "imaging/exr_file.h"
#include "render/display_transform.h"
#include "render/frame_data.h"
#include "render/renderer.h"
#include "render/setting_keys.h"
#include "scene/scene_loader.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "spectral/observer.h"
#include "techniques/technique_pass.h"

namespace prism::app {

render::FrameSettings frameSettings(const SettingsOptions& o) {
  render::FrameSettings s;
  for (const auto& [key, value] : o.values) {
    if (!render::applyFrameSetting(s, key, value)) throw Error(fmt::format("unknown setting \"{}\"", key));
  }
  if (!o.camera.empty()) {
    cameraOption(o.camera);
    s.observer = o.camera;
  }
  render::validate(s);
  return s;
}

bool isDisplayKey(std::string_view key) {
  return key == "white-balance" || key == "adaptation" || key == "tonemap" || key == "display" || key == "dither";
}

void refuseDisplayOptionsOnExr(const SettingsOptions& options, const std::filesystem::path& output) {
  if (lowercaseExtension(output) != ".exr") return;
  for (const auto& [key, value] : options.values)
    if (isDisplayKey(key))
      throw Error(fmt::format("--{} {}: an EXR holds linear tristimulus, before the display transform this shapes "
                              "(write a .png for it)", key, value));
}

void renderToFile(const Scene& scene, const render::FrameSettings& settings, int frames,
                  const std::filesystem::path& output, bool progress) {
  requireWritable(output);  // first, so that an empty name is said to be one
  std::string extension = lowercaseExtension(output);
  if (extension != ".png" && extension != ".exr") {
    throw Error(fmt::format("{}: the output must be a .png or an .exr file", output.string()));
  }
  if (frames < 1) throw Error("--frames: must be at least 1");
  requireNotSceneInput(output, scene);
  render::requireLightCount(scene);  // the renderer's own checks, before the work ahead of them
  render::requireTechniquesShow(scene, settings);
  gpu::HeadlessContext context;
  requireTechniquesFit(scene);  // this GPU's limits, before the work ahead of it too
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  harness::fitOptimisedWavelengths(scene, settings, table);
  harness::precomputeTechniques(scene);
  render::Renderer renderer(scene, table, settings);
  // The matrix a camera's image goes through is fitted under the scene's light (display_transform.h).
  if (const std::optional<double> c = renderer.context().display.cameraChartConditioning)
    warnIfIllPosed(*c, "the scene's light", settings.observer);
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
  const render::FrameContext& frame = renderer.context();
  imaging::writeExr(output, image,
                    imaging::tristimulusExr(*frame.tristimulusObserver,
                                            render::displayWhiteLuminance(settings.display.ev100.value_or(scene.camera.ev100)),
                                            frame.display.tristimulusToXyz));
}

namespace {

// What a mode that draws no wavelengths renders with instead.
std::string_view ownWavelengths(render::RenderMode mode) {
  switch (mode) {
    case render::RenderMode::Rgb: return "renders three RGB channels";
    case render::RenderMode::Reference: return "renders its own 472 wavelengths over 360–830 nm";
    case render::RenderMode::Optimised4: return "renders the sky's four optimised wavelengths";
    default: return "draws wavelengths";
  }
}

// An option the image would not show is refused: sampling or upsampling with a mode that ignores
// it, the display transform's with an EXR (linear tristimulus, before it).
void refuseUnusedOptions(const SettingsOptions& options, const render::FrameSettings& settings,
                         const std::filesystem::path& output) {
  const bool upsamples = settings.mode != render::RenderMode::Rgb && settings.mode != render::RenderMode::Naive;
  refuseDisplayOptionsOnExr(options, output);
  for (const auto& [key, value] : options.values) {
    if (!render::usesSampling(settings.mode) && (key == "wavelengths" || key == "range" || key == "strategy"))
      throw Error(fmt::format("--{} {}: mode {} {}, so it has no use for it (naive and jakob-hanika do)", key, value,
                              render::renderModeName(settings.mode), ownWavelengths(settings.mode)));
    if (!upsamples && (key == "lookup" || key == "gbuffer"))
      throw Error(fmt::format("--{} {}: mode {} upsamples no colour with the Jakob–Hanika table, so it has no use for "
                              "it (jakob-hanika, reference and optimised4 do)",
                              key, value, render::renderModeName(settings.mode)));
  }
}

}  // namespace

void runRender(const RenderOptions& options) {
  render::FrameSettings settings = frameSettings(options.settings);
  refuseUnusedOptions(options.settings, settings, options.output);
  if (options.frames < 1) throw Error("--frames: must be at least 1");
  Scene scene = loadScene(options.scene, options.sets);
  // Frames that cannot differ are rendered once: their mean is the first.
  int frames = render::framesDiffer(settings) ? options.frames : 1;
  renderToFile(scene, settings, frames, options.output, true);
  std::string repeated;
  if (frames != options.frames) {
    std::string what = render::usesSampling(settings.mode)
                           ? fmt::format("the {} strategy", samplingStrategyName(settings.sampling.strategy))
                           : fmt::format("{} mode", render::renderModeName(settings.mode));
    repeated = fmt::format(", not {}: {} renders the same frame every time", options.frames, what);
  }
  fmt::print("wrote {} ({}x{}, {} mode, {} frame{}{})\n", options.output.string(), settings.width, settings.height,
             render::renderModeName(settings.mode), frames, frames == 1 ? "" : "s", repeated);
}

}  // namespace prism::app

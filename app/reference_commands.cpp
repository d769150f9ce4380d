#include "app/reference_commands.h"

#include <fmt/format.h>

#include "app/camera_option.h"
#include "app/option_error.h"
#include "batch/reference_part.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "core/file_extension.h"
#include "core/task_split.h"
#include "harness/display_png.h"
#include "harness/progress_bar.h"
#include "harness/upsampling_table.h"
#include "imaging/exr_file.h"
#include "reference/path_tracer.h"
#include "render/display_transform.h"
#include "render/frame_settings.h"
#include "scene/scene_emission.h"
#include "scene/scene_loader.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"

namespace prism::app {
namespace {

// What a camera's reference image is shown through: its matrix under the scene's light, as the
// renderer's frame of the scene is (render::FrameContext).
std::optional<Eigen::Matrix3d> sceneCameraToXyz(const Scene& scene, const RgbToSpectrumTable& table,
                                                const std::string& observerName) {
  const Observer& camera = observer(observerName);
  if (!camera.isCamera) return std::nullopt;
  const Spectrum light = sceneEmission(scene, colourSpace(scene.colourSpace), table);
  return render::cameraToXyz(camera, &light);
}

// The rows and paths the options ask for: all, or a part's.
reference::ReferenceRegion region(const ReferenceOptions& o, const reference::ReferenceSettings& s) {
  reference::ReferenceRegion r = reference::ReferenceRegion::whole(s);
  if (!o.tile.empty()) {
    TaskIndex tile = parseTaskIndex(o.tile, "--tile");
    if (tile.count > s.height) {
      throw Error(fmt::format("--tile {}: {} tiles of rows need at least {} rows, the image has {}", o.tile, tile.count,
                              tile.count, s.height));
    }
    IndexRange rows = shareOf(tile, s.height);
    r.rowBegin = rows.begin;
    r.rowEnd = rows.end;
  }
  if (!o.samples.empty()) {
    IndexRange samples = parseIndexRange(o.samples, "--samples");
    r.sampleBegin = samples.begin;
    r.sampleEnd = samples.end;
  }
  reference::validate(r, s);
  return r;
}

// A part of the render: skipped when OUT already holds it whole.
void runReferencePart(const ReferenceOptions& o, const Scene& scene, const reference::ReferenceSettings& settings,
                      float ev100) {
  if (lowercaseExtension(o.output) != ".exr") {
    throw Error(fmt::format("{}: a part of a render (--tile, --samples) is an .exr file", o.output.string()));
  }
  if (!o.variance.empty()) throw Error("--variance: a part holds its variance; name the file to `prism merge`");
  const reference::ReferenceRegion r = region(o, settings);
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  batch::ReferencePartHeader header = batch::partHeader(o.scene, o.sets, scene, settings, r, ev100);
  header.cameraToXyz = sceneCameraToXyz(scene, table, settings.observer);  // a complete part's must be this too
  const std::string what = fmt::format("rows {}–{}, samples {}:{} of {}", r.rowBegin, r.rowEnd - 1, r.sampleBegin,
                                       r.sampleEnd, settings.samplesPerPixel);
  std::error_code ec;
  if (std::filesystem::exists(o.output, ec)) {
    try {
      const batch::ReferencePartHeader existing = batch::readReferencePart(o.output).header;
      if (existing.identity() == header.identity() && existing.region == r && existing.cameraToXyz == header.cameraToXyz) {
        fmt::print("{}: complete ({}), skipped\n", o.output.string(), what);
        return;
      }
      fmt::print("{}: a part of another render or region; tracing it again\n", o.output.string());
    } catch (const Error& e) {
      fmt::print("{}: tracing it again ({})\n", o.output.string(), e.what());
    }
  }
  requireWritable(o.output);
  requireNotSceneInput(o.output, scene);
  harness::ProgressBar bar("tracing " + o.output.filename().string());
  reference::ReferenceImage image = reference::renderReference(
      scene, table, settings, r, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
  imaging::requireFiniteOutput(image.tristimulus, o.output.string());
  batch::writeReferencePart(o.output, header, image);
  fmt::print("wrote {} ({})\n", o.output.string(), what);
}

}  // namespace

reference::ReferenceSettings referenceSettings(const ReferenceOptions& o) {
  reference::ReferenceSettings s;
  s.width = o.width;
  s.height = o.height;
  s.samplesPerPixel = o.samplesPerPixel;
  s.transport = fromOption("--transport", [&] { return reference::lightTransportFromName(o.transport); });
  if (o.maxDepth) {
    if (s.transport != reference::LightTransport::Global)
      throw Error(fmt::format("--max-depth {}: only with --transport global (direct light ends each path at its first "
                              "surface)", *o.maxDepth));
    s.maxDepth = *o.maxDepth;
  }
  s.filter = fromOption("--filter", [&] { return reference::pixelFilterFromName(o.filter); });
  s.observer = o.camera.empty() ? o.observer : o.camera;
  if (!o.camera.empty()) cameraOption(o.camera);
  if (!o.range.empty()) {
    if (o.range.size() != 2) throw Error("--range: expected MIN,MAX in nm");
    s.wavelengths.minNm = o.range[0];
    s.wavelengths.maxNm = o.range[1];
    fromOption("--range", [&] { validateWavelengthRange(o.range[0], o.range[1]); });
  }
  s.wavelengths.strategy = samplingStrategyFromName(o.strategy);
  s.seed = o.seed;
  s.threads = o.threads;
  reference::validate(s);
  return s;
}

void checkReferenceOutputs(const std::filesystem::path& output, const std::filesystem::path& variance) {
  if (output.empty()) throw Error("an output's file name is empty");
  if (lowercaseExtension(output) != ".png" && lowercaseExtension(output) != ".exr") {
    throw Error(fmt::format("{}: the output must be a .png or an .exr file", output.string()));
  }
  if (!variance.empty() && lowercaseExtension(variance) != ".exr") {
    throw Error(fmt::format("{}: the variance image must be an .exr file", variance.string()));
  }
  requireOtherFile(variance, output, "the image (-o)");
}

bool isReferenceDisplayKey(std::string_view key) { return isDisplayKey(key) && key != "dither"; }

render::DisplaySettings referenceDisplay(const SettingsOptions& display, const std::filesystem::path& output) {
  for (const auto& [key, value] : display.values) PRISM_CHECK(isReferenceDisplayKey(key));
  refuseDisplayOptionsOnExr(display, output);
  return frameSettings(display).display;
}

void writeReferenceImage(const reference::ReferenceImage& image, const std::string& observerName, float ev100,
                         const render::DisplaySettings& display, const std::filesystem::path& output,
                         const std::filesystem::path& variance, const std::optional<Eigen::Matrix3d>& cameraToXyz) {
  const Observer& tristimulusObserver = observer(observerName);
  PRISM_CHECK(!tristimulusObserver.isCamera || cameraToXyz);
  imaging::requireFiniteOutput(image.tristimulus, output.string());
  if (lowercaseExtension(output) == ".exr") {
    imaging::writeExr(output, image.tristimulus,
                      imaging::tristimulusExr(tristimulusObserver, render::displayWhiteLuminance(ev100),
                                              cameraToXyz.value_or(Eigen::Matrix3d::Identity())));
  } else {
    render::DisplaySettings shown = display;
    shown.ev100 = ev100;
    harness::displayImage(image.tristimulus, shown, tristimulusObserver, ev100, cameraToXyz).write(output);
  }
  // The variance is in squared units and no colour: not something compare should take for one.
  if (!variance.empty()) imaging::writeExr(variance, image.variance, {.colour = imaging::ColourMeaning::OtherRgb});
}

void runReference(const ReferenceOptions& o) {
  setAllThreads(o.threads);  // Embree's BVH build too, not only the paths
  if (o.ev100) fromOption("--ev", [&] { render::validateEv100(*o.ev100); });
  if (o.tile.empty() && o.samples.empty()) checkReferenceOutputs(o.output, o.variance);
  const render::DisplaySettings display = referenceDisplay(o.display, o.output);
  Scene scene = loadScene(o.scene, o.sets);
  reference::requireTraceable(scene);  // before the upsampling table, which a cold cache builds first
  reference::ReferenceSettings settings = referenceSettings(o);
  const float ev100 = o.ev100.value_or(scene.camera.ev100);
  if (!o.tile.empty() || !o.samples.empty()) {
    runReferencePart(o, scene, settings, ev100);
    return;
  }
  requireWritable(o.output);
  requireNotSceneInput(o.output, scene);
  if (!o.variance.empty()) {
    requireWritable(o.variance);
    requireNotSceneInput(o.variance, scene);
  }
  const RgbToSpectrumTable& table = harness::upsamplingTable(scene);
  harness::ProgressBar bar("tracing " + o.output.filename().string());
  reference::ReferenceImage image = reference::renderReference(
      scene, table, settings, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
  writeReferenceImage(image, settings.observer, ev100, display, o.output, o.variance,
                      sceneCameraToXyz(scene, table, settings.observer));
  fmt::print("wrote {} ({}x{}, {} paths per pixel, {} lighting)\n", o.output.string(), settings.width,
             settings.height, settings.samplesPerPixel, o.transport);
}

}  // namespace prism::app

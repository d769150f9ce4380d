#include "harness/gallery.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <fstream>
#include <span>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "gpu/headless_context.h"
#include "harness/colour_checker_chart.h"
#include "harness/contact_sheet.h"
#include "harness/display_png.h"
#include "harness/html_report.h"
#include "harness/nebula_display.h"
#include "harness/progress_bar.h"
#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "imaging/image_difference.h"
#include "imaging/png_file.h"
#include "render/display_transform.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/wavelength_fit.h"
#include "techniques/nebula/gpu/nebula_gpu_marcher.h"
#include "techniques/nebula/nebula_scene.h"
#include "core/atomic_file.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/file_extension.h"

namespace prism::harness {
namespace {

// The images the gallery writes, named once for the renders, the page and the check of the
// outputs before any work: a file suffix, the figure's caption and the image's alternative text
// (after the scene's name).
struct View {
  const char* suffix;
  const char* caption;
  const char* alt;
};
constexpr std::array<View, 2> kSurfaceViews{{{"_rgb", "RGB", " in RGB mode"}, {"_spectral", "spectral", " in spectral mode"}}};
constexpr std::array<View, 3> kSkyViews{
    {{"_rgb", "RGB-3", ", RGB-3"}, {"_optimised4", "optimised4", ", optimised4"}, {"_reference", "reference", ", reference"}}};
constexpr std::array<View, 2> kNebulaViews{
    {{"_hubble", "Hubble palette", " in the Hubble palette"}, {"_natural", "natural colour", " in natural colour"}}};
constexpr const char* kChartFile = "colorchecker.png";
constexpr const char* kIndexFile = "index.html";
constexpr const char* kSheetFile = "contact_sheet.png";

// The contact sheet's images, each with its label, in the gallery's order (a deque: the cells
// point into it).
using SheetImages = std::deque<std::pair<imaging::PngImage, std::string>>;

std::string viewFile(const std::string& name, const View& view) { return name + view.suffix + ".png"; }

// A scene's views: with a technique of its own optimised wavelengths (the sky), RGB-3, optimised-4
// and the reference; otherwise RGB and spectral.
std::span<const View> sceneViews(bool sky) {
  return sky ? std::span<const View>(kSkyViews) : std::span<const View>(kSurfaceViews);
}

struct Entry {
  std::string name;
  std::string description;
  imaging::DifferenceStats difference;  // RGB vs spectral (sky scenes: RGB-3 vs the reference)
  // Scenes with a technique of their own optimised wavelengths (the sky): RGB-3, optimised-4 and
  // the reference side by side.
  bool sky = false;
  imaging::DifferenceStats optimisedDifference;  // optimised-4 vs the reference
};

// A nebula (scenes/nebula/*.json) by projection on the GPU in both filter sets, each held to the
// CPU's reference (double integration over wavelength).
struct NebulaEntry {
  std::string name;
  double hubbleError = 0.0;   // max relative error per pixel (pixels ≥ 1 % of their channel's peak)
  double naturalError = 0.0;
};

// The nebula of `file` at its camera's size or within `most` pixels a side, in the Hubble palette
// and in natural colour (one precomputation and one march, refiltered and finished again), written
// into `folder` as kNebulaViews name them; the entry holds each render's max relative error
// against the reference; both images go on the sheet.
void renderNebula(const std::filesystem::path& file, int most, const std::filesystem::path& folder, NebulaEntry& entry,
                  SheetImages& sheet) {
  nebula::NebulaScene scene = nebula::loadNebulaScene(file);
  scene.model.filters = "hubble";
  nebula::NebulaCamera& camera = scene.model.camera;
  if (camera.width > most || camera.height > most) nebula::scaleImage(camera, most);
  nebula::RenderSettings settings;
  settings.steps = scene.steps;
  const nebula::NebulaRenderer hubble(std::move(scene.model), settings);
  const nebula::NebulaRenderer natural(hubble, "cie1931", hubble.model().passbands);
  settings.method = nebula::Method::Projection;
  nebula::NebulaGpuMarcher marcher(hubble);
  marcher.march(settings);
  for (const nebula::NebulaRenderer* renderer : {&hubble, &natural}) {
    const bool palette = renderer == &hubble;
    if (!palette) PRISM_CHECK(marcher.refilter(natural));
    const nebula::NebulaImage image = marcher.finish();
    settings.method = nebula::Method::Reference;
    (palette ? entry.hubbleError : entry.naturalError) = nebula::maxRelativeError(image, renderer->render(settings));
    const View& view = kNebulaViews[palette ? 0 : 1];
    imaging::PngImage png = nebulaDisplayPng(image, palette);
    png.write(folder / viewFile(entry.name, view));
    sheet.emplace_back(std::move(png), fmt::format("{} ({})", entry.name, view.caption));
  }
}

imaging::FloatImage tristimulus(const render::Renderer& renderer, int width, int height) {
  imaging::FloatImage image(width, height, 3);
  image.pixels = renderer.readMeanTristimulus();
  return image;
}

std::string description(const std::filesystem::path& file) {
  std::ifstream in(file);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() && j.contains("description") && j["description"].is_string()
             ? j["description"].get<std::string>()
             : std::string();
}

std::string indexHtml(const std::vector<Entry>& entries, const std::vector<NebulaEntry>& nebulae,
                      const GalleryOptions& o) {
  HtmlPage page("Prism gallery");
  page.paragraph("All of it at once, the spectral images shrunk (the sky's: optimised4):");
  page.image({kSheetFile, "every scene's spectral image and both views of every nebula, in a grid"});
  page.paragraph(fmt::format(
      "Each scene rendered by <code>prism demo</code> at {}×{} in RGB mode (three channels, the common "
      "practice) and in spectral mode (Jakob–Hanika upsampling, one frame of {} wavelengths and a 3×{} matrix "
      "fitted for the scene's lights — the optimised strategy, the renderer's default — CIE 1931). ΔE00 is "
      "CIEDE2000 between the two, in XYZ before the display transform, relative to the exposure's white "
      "(1.2·2^EV100 cd/m²).",
      o.width, o.height, o.wavelengths, o.wavelengths));
  page.paragraph("Scenes under the spectral sky are rendered three ways instead: RGB-3 (680, 550, 440 nm as R, G, "
                 "B), the four optimised wavelengths (optimised4) and the reference (472 wavelengths), one frame each "
                 "(all deterministic), with ΔE00 of the first two against the reference.");
  std::vector<std::vector<std::string>> rows;
  auto row = [&](const std::string& name, const std::string& label, const imaging::DifferenceStats& d) {
    rows.push_back({htmlLink("#" + name, label), fmt::format("{:.2f}", d.meanDeltaE), fmt::format("{:.2f}", d.p95DeltaE),
                    fmt::format("{:.2f}", d.maxDeltaE)});
  };
  for (const Entry& e : entries) {
    if (e.sky) {
      row(e.name, e.name + ": RGB-3 vs reference", e.difference);
      row(e.name, e.name + ": optimised4 vs reference", e.optimisedDifference);
    } else {
      row(e.name, e.name, e.difference);
    }
  }
  page.table({"scene", "mean ΔE00", "p95", "max"}, rows);
  auto figures = [&page](const std::string& name, std::span<const View> views) {
    for (const View& view : views) page.figure({{viewFile(name, view), name + view.alt}}, view.caption);
  };
  for (const Entry& e : entries) {
    page.beginSection(e.name, e.name);
    page.paragraph(htmlEscape(e.description));
    figures(e.name, sceneViews(e.sky));
    page.endSection();
  }
  for (const NebulaEntry& n : nebulae) {
    page.beginSection(n.name, n.name + " (spectral nebula)");
    page.paragraph(fmt::format(
        "Barrès 2023's spectral nebula: a density grid lit by blackbody stars through dust, with the emission lines "
        "of ionised gas, marched on the GPU by projection on the greedy exp(−a/λ) basis (4 elements). "
        "Largest relative error per pixel against the CPU's double integration over wavelength (pixels at least "
        "1 % of their channel's peak): {:.3g} % in the Hubble palette ([S II] 6716 → R, Hα → G, [O III] → B, "
        "each channel stretched to its 99.5th percentile), {:.3g} % in natural colour (CIE 1931).",
        100.0 * n.hubbleError, 100.0 * n.naturalError));
    figures(n.name, kNebulaViews);
    page.endSection();
  }
  page.beginSection("", "ColorChecker");
  page.paragraph("The 24 patches lit spectrally by D65, A, F2 and F11, white-balanced to D65.");
  page.image({kChartFile, "ColorChecker chart"});
  page.endSection();
  return page.html();
}

// Whether a scene has a technique of its own optimised wavelengths (the sky): sceneViews(true).
bool showsOptimisedWavelengths(const Scene& scene) {
  return std::ranges::any_of(scene.techniques.all(),
                             [](const auto& t) { return t->optimisedWavelengths().has_value(); });
}

// Error before any work unless every file the gallery writes into `folder` can be written and is
// none of the files it reads (a scene's texture beside it, when the gallery is written into the
// scenes' folder: it was replaced by a render, and a later scene drew that).
void requireOutputsClear(const std::filesystem::path& folder, const std::vector<Scene>& scenes,
                         const std::vector<std::filesystem::path>& nebulaFiles) {
  std::vector<std::filesystem::path> outputs{folder / kChartFile, folder / kIndexFile, folder / kSheetFile};
  for (const Scene& scene : scenes) {
    for (const View& view : sceneViews(showsOptimisedWavelengths(scene)))
      outputs.push_back(folder / viewFile(scene.file.stem().string(), view));
  }
  std::vector<nebula::NebulaSceneFile> nebulae;
  for (const std::filesystem::path& file : nebulaFiles) {
    nebulae.push_back(nebula::readNebulaScene(file));
    for (const View& view : kNebulaViews) outputs.push_back(folder / viewFile(file.stem().string(), view));
  }
  for (const std::filesystem::path& output : outputs) {
    requireWritable(output);
    for (const Scene& scene : scenes) requireNotSceneInput(output, scene);
    for (std::size_t i = 0; i < nebulae.size(); ++i) {
      requireOtherFile(output, nebulaFiles[i], "a nebula's scene file");
      requireOtherFile(output, nebulae[i].source.file, "a nebula's density file");
    }
  }
}

}  // namespace

void runGallery(const GalleryOptions& o) {
  std::filesystem::path sceneDir = o.scenes.empty() ? exampleSceneDirectory() : o.scenes;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  if (std::filesystem::exists(sceneDir, ec) && !std::filesystem::is_directory(sceneDir, ec))
    throw Error(sceneDir.string() + ": not a folder (--scenes names the folder of the scene files)");
  if (std::filesystem::is_directory(sceneDir)) {
    for (const auto& entry : std::filesystem::directory_iterator(sceneDir)) {
      if (lowercaseExtension(entry.path()) == ".json") files.push_back(entry.path());
    }
  }
  if (files.empty()) throw Error(sceneDir.string() + ": no scene files (*.json) to render");
  std::sort(files.begin(), files.end());
  // Bad options and an output that cannot be made fail before any long work. The spectral images
  // are fitted sets (the optimised strategy), whose limits are narrower than the renderer's.
  if (o.wavelengths < 4 || o.wavelengths > kMaxFittedWavelengths || o.wavelengths % 4 != 0)
    throw Error(fmt::format("--wavelengths {}: the gallery fits 4 to {} wavelengths, a multiple of 4", o.wavelengths,
                            kMaxFittedWavelengths));
  render::FrameSettings check;
  check.width = o.width;
  check.height = o.height;
  check.sampling.count = o.wavelengths;
  render::validate(check);
  requireWritableFolder(o.output);
  // Loaded once, then checked, precomputed and rendered (all held at once: a folder of large
  // models costs their sum in memory).
  std::vector<Scene> scenes;
  for (const std::filesystem::path& file : files) scenes.push_back(loadScene(file));
  // Nebulae (scenes/nebula/*.json: a section of their own, not surface scenes), at their cameras'
  // sizes, within the gallery's height.
  std::vector<std::filesystem::path> nebulaFiles;
  if (std::filesystem::is_directory(sceneDir / "nebula")) {
    for (const auto& entry : std::filesystem::directory_iterator(sceneDir / "nebula"))
      if (lowercaseExtension(entry.path()) == ".json") nebulaFiles.push_back(entry.path());
  }
  std::sort(nebulaFiles.begin(), nebulaFiles.end());
  requireOutputsClear(o.output, scenes, nebulaFiles);
  std::filesystem::create_directories(o.output);
  for (const Scene& scene : scenes) precomputeTechniques(scene);  // bars of their own

  DemoOptions chart;
  chart.output = o.output / kChartFile;
  chart.adaptation = o.adaptation;
  writeColourCheckerChart(chart);

  gpu::HeadlessContext context;
  ProgressBar bar("gallery");
  std::vector<Entry> entries;
  SheetImages sheet;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Scene& scene = scenes[i];
    render::FrameSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.mode = render::RenderMode::Rgb;
    settings.sampling.count = o.wavelengths;
    render::Renderer renderer(scene, upsamplingTable(scene), settings);
    renderer.renderFrame();
    imaging::PngImage rgb = displayPng(renderer);
    imaging::FloatImage rgbXyz = tristimulus(renderer, o.width, o.height);
    Entry e;
    e.name = files[i].stem().string();
    e.description = description(files[i]);
    // In XYZ before the display transform, relative to the exposure's white: dither and tone
    // mapping are not differences between the modes.
    double white = render::displayWhiteLuminance(scene.camera.ev100);
    auto difference = [&](const imaging::FloatImage& test, const imaging::FloatImage& reference) {
      return imaging::compareImages(imaging::linearInput(test, imaging::ColourMeaning::Xyz, white),
                                    imaging::linearInput(reference, imaging::ColourMeaning::Xyz, white))
          .stats;
    };
    if (showsOptimisedWavelengths(scene)) {
      e.sky = true;
      settings.mode = render::RenderMode::Optimised4;
      renderer.setSettings(settings);
      renderer.renderFrame();
      imaging::PngImage optimised = displayPng(renderer);
      imaging::FloatImage optimisedXyz = tristimulus(renderer, o.width, o.height);
      settings.mode = render::RenderMode::Reference;
      renderer.setSettings(settings);
      renderer.renderFrame();
      imaging::PngImage reference = displayPng(renderer);
      imaging::FloatImage referenceXyz = tristimulus(renderer, o.width, o.height);
      e.difference = difference(rgbXyz, referenceXyz);
      e.optimisedDifference = difference(optimisedXyz, referenceXyz);
      for (std::size_t v = 0; const imaging::PngImage* image : {&rgb, &optimised, &reference})
        image->write(o.output / viewFile(e.name, kSkyViews[v++]));
      sheet.emplace_back(std::move(optimised), fmt::format("{} ({})", e.name, kSkyViews[1].caption));
      entries.push_back(std::move(e));
      bar.update(i + 1, scenes.size());
      continue;
    }
    settings.mode = render::RenderMode::JakobHanika;
    renderer.setSettings(settings);
    renderer.renderFrame();
    imaging::PngImage spectral = displayPng(renderer);
    imaging::FloatImage spectralXyz = tristimulus(renderer, o.width, o.height);
    e.difference = difference(spectralXyz, rgbXyz);
    rgb.write(o.output / viewFile(e.name, kSurfaceViews[0]));
    spectral.write(o.output / viewFile(e.name, kSurfaceViews[1]));
    sheet.emplace_back(std::move(spectral), e.name);
    entries.push_back(std::move(e));
    bar.update(i + 1, scenes.size());
  }
  std::vector<NebulaEntry> nebulae;
  ProgressBar nebulaBar("gallery: nebulae, each against its reference");
  for (std::size_t i = 0; i < nebulaFiles.size(); ++i) {
    NebulaEntry n;
    n.name = nebulaFiles[i].stem().string();
    renderNebula(nebulaFiles[i], o.height, o.output, n, sheet);
    nebulaBar.update(i + 1, nebulaFiles.size());
    nebulae.push_back(std::move(n));
  }
  std::vector<SheetCell> cells;
  for (const auto& [image, label] : sheet) cells.push_back({&image, label});
  contactSheet(cells, {.columns = 4, .cellWidth = std::clamp(o.width / 2, 16, 4096), .cellHeight = std::clamp(o.height / 2, 16, 4096)})
      .write(o.output / kSheetFile);
  writeFileAtomically(o.output / kIndexFile, indexHtml(entries, nebulae, o));
  fmt::print("{:<24} {:>10} {:>8} {:>8}\n", "scene (RGB vs spectral)", "mean ΔE00", "p95", "max");
  for (const Entry& e : entries) {
    if (e.sky) {
      fmt::print("{:<24} {:>10.2f} {:>8.2f} {:>8.2f}\n", e.name + " RGB-3 vs ref", e.difference.meanDeltaE,
                 e.difference.p95DeltaE, e.difference.maxDeltaE);
      fmt::print("{:<24} {:>10.2f} {:>8.2f} {:>8.2f}\n", e.name + " opt4 vs ref", e.optimisedDifference.meanDeltaE,
                 e.optimisedDifference.p95DeltaE, e.optimisedDifference.maxDeltaE);
      continue;
    }
    fmt::print("{:<24} {:>10.2f} {:>8.2f} {:>8.2f}\n", e.name, e.difference.meanDeltaE,
               e.difference.p95DeltaE, e.difference.maxDeltaE);
  }
  for (const NebulaEntry& n : nebulae) {
    fmt::print("{:<24} max relative error per pixel, GPU projection against the reference: Hubble {:.3g} %, "
               "natural {:.3g} %\n",
               n.name + " (nebula)", 100.0 * n.hubbleError, 100.0 * n.naturalError);
  }
  fmt::print("wrote {}\n", (o.output / kIndexFile).string());
}

}  // namespace prism::harness

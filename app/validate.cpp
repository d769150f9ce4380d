#include "app/validate.h"

#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/progress_bar.h"
#include "app/reference_commands.h"
#include "app/upsampling_table.h"
#include "gpu/headless_context.h"
#include "imaging/exr_file.h"
#include "imaging/heatmap.h"
#include "imaging/image_difference.h"
#include "reference/path_tracer.h"
#include "render/display_transform.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/atomic_file.h"
#include "spectral/data_files.h"
#include "spectral/error.h"

namespace prism::app {
namespace {

struct Experiment {
  const char* scene;
  const char* light;
};
constexpr Experiment kExperiments[] = {
    {"spheres_d65", "D65"},
    {"spheres_led", "the thesis's LED lamp (LSPDD Globe A19)"},
    {"spheres_blue_led", "a narrow-band blue LED (450 nm)"},
};

// The thesis's three modes at 200 wavelengths (one frame of the uniform grid), and the real-time
// setting, 16 wavelengths a frame: as a still camera sees it (the uniform grid rotated every
// frame, 32 frames accumulated) and as one frame alone.
struct Mode {
  const char* name;
  render::RenderMode mode;
  int wavelengths;
  SamplingStrategy strategy;
  int frames;
};
constexpr Mode kModes[] = {
    {"rgb", render::RenderMode::Rgb, 16, SamplingStrategy::Uniform, 1},
    {"naive-200", render::RenderMode::Naive, 200, SamplingStrategy::Uniform, 1},
    {"jakob-hanika-200", render::RenderMode::JakobHanika, 200, SamplingStrategy::Uniform, 1},
    {"jakob-hanika-16", render::RenderMode::JakobHanika, 16, SamplingStrategy::Rotated, 32},
    {"jakob-hanika-16-1frame", render::RenderMode::JakobHanika, 16, SamplingStrategy::Uniform, 1},
};

struct Bound {
  const char* scene;
  const char* mode;
  double maxMeanDeltaE;
};
constexpr Bound kBounds[] = {
    {"spheres_d65", "jakob-hanika-16", 0.5},
    {"spheres_blue_led", "jakob-hanika-16", 1.0},
};

struct Result {
  std::string scene, mode;
  imaging::DifferenceStats stats;
};

constexpr double kHeatScale = 5.0;  // ΔE00 at the top of the heat maps and histograms

std::string resultTable(const std::vector<Result>& results) {
  std::ostringstream out;
  out << fmt::format("{:<18} {:<24} {:>9} {:>8} {:>8} {:>8} {:>8}\n", "scene", "mode", "mean ΔE00",
                     "median", "p95", "max", "MAE 8b");
  for (const Result& r : results) {
    out << fmt::format("{:<18} {:<24} {:>9.3f} {:>8.3f} {:>8.3f} {:>8.2f} {:>8.3f}\n", r.scene, r.mode,
                       r.stats.meanDeltaE, r.stats.medianDeltaE, r.stats.p95DeltaE, r.stats.maxDeltaE,
                       r.stats.mae8);
  }
  return out.str();
}

std::string indexHtml(const std::vector<Result>& results, const std::vector<std::string>& failures,
                      int width, int height, int spp) {
  std::ostringstream h;
  h << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>Prism validation"
       "</title>\n<style>body{font-family:sans-serif;background:#222;color:#ddd;margin:2em}figure{"
       "display:inline-block;margin:0 1em 1em 0;vertical-align:top}figcaption{text-align:center}"
       "td,th{padding:0 1em;text-align:right}.fail{color:#f66}</style></head><body>\n"
       "<h1>Prism validation</h1>\n";
  h << fmt::format("<p>The rasteriser against the reference path tracer (direct lighting, {} paths "
                   "per pixel at the pixel centres, 4 hero wavelengths each), {}×{}. ΔE00 is CIEDE2000 "
                   "in XYZ before the display transform relative to the exposure's white; MAE is on "
                   "8-bit sRGB (0–255) after it. Heat maps and histograms span ΔE00 0–{}.</p>\n",
                   spp, width, height, kHeatScale);
  h << (failures.empty() ? "<p>Every bound holds.</p>\n" : "<p class=\"fail\">Broken bounds:</p><ul>\n");
  for (const std::string& f : failures) h << "<li class=\"fail\">" << f << "</li>\n";
  if (!failures.empty()) h << "</ul>\n";
  h << "<table><tr><th>scene</th><th>mode</th><th>mean ΔE00</th><th>median</th><th>p95</th>"
       "<th>max</th><th>MAE</th></tr>\n";
  for (const Result& r : results) {
    h << fmt::format("<tr><td>{}</td><td>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td>"
                     "<td>{:.2f}</td><td>{:.3f}</td></tr>\n", r.scene, r.mode, r.stats.meanDeltaE,
                     r.stats.medianDeltaE, r.stats.p95DeltaE, r.stats.maxDeltaE, r.stats.mae8);
  }
  h << "</table>\n";
  for (const Experiment& e : kExperiments) {
    h << fmt::format("<section><h2>{} — under {}</h2>\n<figure><img src=\"{}_reference.png\" alt=\"reference\">"
                     "<figcaption>reference</figcaption></figure><br>\n", e.scene, e.light, e.scene);
    for (const Mode& m : kModes) {
      h << fmt::format("<figure><img src=\"{0}_{1}.png\" alt=\"{1}\"><br><img src=\"{0}_{1}_heatmap.png\" "
                       "alt=\"ΔE00 heat map\"><br><img src=\"{0}_{1}_histogram.png\" width=\"320\" "
                       "alt=\"ΔE00 histogram\"><figcaption>{1}</figcaption></figure>\n", e.scene, m.name);
    }
    h << "</section>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

nlohmann::json toJson(const std::vector<Result>& results, const std::vector<std::string>& failures,
                      int width, int height, int spp) {
  nlohmann::json rows = nlohmann::json::array();
  for (const Result& r : results) {
    rows.push_back({{"scene", r.scene}, {"mode", r.mode}, {"mean_delta_e", r.stats.meanDeltaE},
                    {"median_delta_e", r.stats.medianDeltaE}, {"p95_delta_e", r.stats.p95DeltaE},
                    {"max_delta_e", r.stats.maxDeltaE}, {"mae_8bit", r.stats.mae8},
                    {"relative_error", r.stats.relativeError}});
  }
  return {{"width", width}, {"height", height}, {"reference_paths_per_pixel", spp},
          {"results", rows}, {"failures", failures}};
}

}  // namespace

int runValidate(const ValidateOptions& o) {
  const int width = o.quick ? 240 : 640, height = o.quick ? 135 : 360, spp = o.quick ? 64 : 256;
  const std::filesystem::path sceneDir = o.scenes.empty() ? exampleSceneDirectory() : o.scenes;
  std::filesystem::create_directories(o.output);
  RgbToSpectrumTable table = upsamplingTable("srgb");
  gpu::HeadlessContext context;

  std::vector<Result> results;
  ProgressBar bar("validate");
  const std::size_t total = std::size(kExperiments) * (1 + std::size(kModes));
  std::size_t done = 0;
  for (const Experiment& e : kExperiments) {
    Scene scene = loadScene(sceneDir / (std::string(e.scene) + ".json"));
    if (scene.colourSpace != "srgb") throw Error(fmt::format("{}: validate expects an sRGB scene", e.scene));
    const double white = render::displayWhiteLuminance(scene.camera.ev100);

    reference::ReferenceSettings rs;
    rs.width = width;
    rs.height = height;
    rs.samplesPerPixel = spp;
    rs.filter = reference::PixelFilter::Centre;
    reference::ReferenceImage reference = reference::renderReference(scene, table, rs);
    render::FrameSettings display;
    display.width = width;
    display.height = height;
    display.dither = false;
    displayImage(reference.tristimulus, display, scene.camera.ev100)
        .write(o.output / fmt::format("{}_reference.png", e.scene));
    imaging::writeExr(o.output / fmt::format("{}_reference.exr", e.scene), reference.tristimulus,
                      {.colour = imaging::ColourMeaning::Xyz, .displayWhite = white});
    bar.update(++done, total);

    render::Renderer renderer(scene, table, display);  // one renderer, its settings changed per mode
    for (const Mode& m : kModes) {
      render::FrameSettings settings = display;
      settings.mode = m.mode;
      settings.sampling.count = m.wavelengths;
      settings.sampling.strategy = m.strategy;
      renderer.setSettings(settings);
      for (int f = 0; f < m.frames; ++f) renderer.renderFrame();
      imaging::FloatImage image(width, height, 3);
      image.pixels = renderer.readMeanTristimulus();
      displayImage(image, settings, scene.camera.ev100).write(o.output / fmt::format("{}_{}.png", e.scene, m.name));
      imaging::DifferenceOptions options;
      options.keepMap = true;
      imaging::ImageDifference d =
          imaging::compareImages(imaging::linearInput(reference.tristimulus, imaging::ColourMeaning::Xyz, white),
                                 imaging::linearInput(image, imaging::ColourMeaning::Xyz, white), options);
      imaging::heatMap(d.deltaEMap, {.maxDeltaE = kHeatScale, .legend = true})
          .write(o.output / fmt::format("{}_{}_heatmap.png", e.scene, m.name));
      imaging::HistogramOptions histogram;
      histogram.maxDeltaE = kHeatScale;
      imaging::deltaEHistogram(d.deltaEMap, histogram)
          .write(o.output / fmt::format("{}_{}_histogram.png", e.scene, m.name));
      results.push_back({e.scene, m.name, d.stats});
      bar.update(++done, total);
    }
  }

  std::vector<std::string> failures;
  for (const Bound& b : kBounds) {
    for (const Result& r : results) {
      if (r.scene == b.scene && r.mode == b.mode && !(r.stats.meanDeltaE <= b.maxMeanDeltaE)) {
        failures.push_back(fmt::format("{} {}: mean ΔE00 {:.3f} > {}", b.scene, b.mode, r.stats.meanDeltaE,
                                       b.maxMeanDeltaE));
      }
    }
  }
  nlohmann::json json = toJson(results, failures, width, height, spp);
  writeFileAtomically(o.output / "results.json", json.dump(2) + "\n");
  writeFileAtomically(o.output / "index.html", indexHtml(results, failures, width, height, spp));
  if (o.json) {
    fmt::print("{}\n", json.dump(2));
  } else {
    fmt::print("{}", resultTable(results));
    fmt::print("wrote {}\n", (o.output / "index.html").string());
  }
  for (const std::string& f : failures) fmt::print(stderr, "prism: validate: bound broken: {}\n", f);
  return failures.empty() ? 0 : 1;
}

}  // namespace prism::app

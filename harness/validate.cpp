#include "harness/validate.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "gpu/headless_context.h"
#include "harness/display_png.h"
#include "harness/html_report.h"
#include "harness/progress_bar.h"
#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "harness/validate_nebula.h"
#include "harness/validate_parts.h"
#include "imaging/exr_file.h"
#include "imaging/heatmap.h"
#include "imaging/image_difference.h"
#include "reference/path_tracer.h"
#include "render/display_transform.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "core/atomic_file.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "core/task_split.h"

namespace prism::harness {
namespace {

// The thesis's sphere scenes (exposure: each scene camera's), and its D65 scene under F11, whose
// three narrow lines are the hard case for few wavelengths (issue 16). `name` names the results.
struct SphereScene {
  const char* name;
  const char* scene;
  const char* set;  // a scene override, or null
  const char* light;
};
constexpr SphereScene kSphereScenes[] = {
    {"spheres_d65", "spheres_d65", nullptr, "D65"},
    {"spheres_led", "spheres_led", nullptr, "the thesis's LED lamp (LSPDD Globe A19)"},
    {"spheres_blue_led", "spheres_blue_led", nullptr, "a narrow-band blue LED (450 nm)"},
    {"spheres_f11", "spheres_d65", "lights.0.spd=F11", "F11 (a fluorescent lamp of three narrow lines)"},
};

// The reef's camera depths (Jerlov I), the thesis's underwater experiment.
constexpr float kReefDepthsM[] = {1.0f, 5.0f, 10.0f, 20.0f, 50.0f};

// Spectral PRT's example scenes, under their environments (issue 14).
struct PrtScene {
  const char* name;
  const char* environment;
};
constexpr PrtScene kPrtScenes[] = {
    {"prt_macbeth", "an F4 overcast sky"},
    {"prt_metamers", "a D65 overcast sky"},
    {"prt_sky", "Prism's spectral sky, and its sun 15° high as a light"},
};

// The thesis's three modes at 200 wavelengths (one frame of the uniform grid), and the real-time
// setting, 16 wavelengths a frame: as a still camera sees it (the uniform grid, or the lights'
// pdf, rotated every frame, 32 frames accumulated) and as one frame alone (uniform grid, the
// observer's importance, the lights' pdf, the set fitted for the scene's lights). A strategy
// whose wavelengths move between frames has a good and a bad frame, as a moving camera sees them
// one after another: its single frames are measured `singles` times in a row, each alone, and
// their statistics averaged.
struct Mode {
  const char* name;
  render::RenderMode mode;
  int wavelengths;
  SamplingStrategy strategy;
  int frames;
  int singles = 1;
  const char* set = nullptr;  // a scene override of the mode's own (the PRT section's mode)
};
constexpr int kSingleFrames = 8;
constexpr Mode kModes[] = {
    {"rgb", render::RenderMode::Rgb, 16, SamplingStrategy::Uniform, 1},
    {"naive-200", render::RenderMode::Naive, 200, SamplingStrategy::Uniform, 1},
    {"jakob-hanika-200", render::RenderMode::JakobHanika, 200, SamplingStrategy::Uniform, 1},
    {"jakob-hanika-16", render::RenderMode::JakobHanika, 16, SamplingStrategy::Rotated, 32},
    {"jakob-hanika-16-lights", render::RenderMode::JakobHanika, 16, SamplingStrategy::Lights, 32},
    {"jakob-hanika-16-1frame", render::RenderMode::JakobHanika, 16, SamplingStrategy::Uniform, 1},
    {"jakob-hanika-16-1frame-importance", render::RenderMode::JakobHanika, 16, SamplingStrategy::Importance, 1,
     kSingleFrames},
    {"jakob-hanika-16-1frame-lights", render::RenderMode::JakobHanika, 16, SamplingStrategy::Lights, 1,
     kSingleFrames},
    {"jakob-hanika-16-1frame-optimised", render::RenderMode::JakobHanika, 16, SamplingStrategy::Optimised, 1},
};

// PRT's three modes through the same transfer, one frame each (PRT's sums are deterministic),
// against the path tracer under the same environment (direct lighting: the shadowed diffuse
// transfer's integral, before the SH-5 band limit).
constexpr Mode kPrtModes[] = {
    {"prt-spectral", render::RenderMode::JakobHanika, 16, SamplingStrategy::Uniform, 1, 1, "prt.mode=spectral"},
    {"prt-rgb", render::RenderMode::JakobHanika, 16, SamplingStrategy::Uniform, 1, 1, "prt.mode=rgb-prt"},
    {"prt-reference-5nm", render::RenderMode::JakobHanika, 16, SamplingStrategy::Uniform, 1, 1,
     "prt.mode=reference-5nm"},
};

// Single frames' statistics, averaged field by field: added up into `sum`, then divided by the runs.
void addStats(imaging::DifferenceStats& sum, const imaging::DifferenceStats& d) {
  sum.pixelCount = d.pixelCount;
  sum.meanDeltaE += d.meanDeltaE;
  sum.medianDeltaE += d.medianDeltaE;
  sum.p95DeltaE += d.p95DeltaE;
  sum.p99DeltaE += d.p99DeltaE;
  sum.maxDeltaE += d.maxDeltaE;
  sum.thresholdDeltaE = d.thresholdDeltaE;
  sum.fractionAbove += d.fractionAbove;
  sum.mae8 += d.mae8;
  sum.relativeError += d.relativeError;
}
imaging::DifferenceStats averaged(imaging::DifferenceStats sum, int runs) {
  for (double* v : {&sum.meanDeltaE, &sum.medianDeltaE, &sum.p95DeltaE, &sum.p99DeltaE, &sum.maxDeltaE,
                    &sum.fractionAbove, &sum.mae8, &sum.relativeError})
    *v /= runs;
  return sum;
}

struct Bound {
  const char* scene;
  const char* mode;
  double maxMeanDeltaE;
};
constexpr Bound kBounds[] = {
    {"spheres_d65", "jakob-hanika-16", 0.5},
    {"spheres_blue_led", "jakob-hanika-16", 1.0},
};
// A nebula method's bounds on every nebula: projection, analytic and pre-integration below the
// just-noticeable difference at every pixel (ΔE00 1; the paper: indistinguishable from the
// reference); light–density, whose 2D basis misses the light near stars inside the cloud (README),
// on the mean (the spheres' 0.5).
struct NebulaBound {
  nebula::Method method;
  double maxMeanDeltaE;
  double maxMaxDeltaE;
};
constexpr NebulaBound kNebulaBounds[] = {
    {nebula::Method::Projection, 0.5, 1.0},
    {nebula::Method::Analytic, 0.5, 1.0},
    {nebula::Method::PreIntegration, 0.5, 1.0},
    {nebula::Method::LightDensity, 0.5, std::numeric_limits<double>::infinity()},
};
// A mode's mean ΔE00 against the reference at most `maxRatio` times another mode's on the same
// scene and reference plus `maxExcess`, on every scene whose name starts with `scenePrefix`:
// - Spectral PRT's basis (m = 8) against its 5 nm reference through the same transfer: the path
//   tracer's noise and the band limit are common to both, the basis's own error is what is left.
// - Under water, the default mode at most half RGB's at every depth of the reef: the thesis's
//   underwater claim, that spectral rendering follows water's absorption where RGB's three
//   coefficients cannot. Measured 0.22 of RGB's at 1 m and at 50 m (640×360, README), 0.33 and
//   0.23 with --quick (32 paths: the reference's noise is in both).
struct RelativeBound {
  const char* scenePrefix;
  const char* mode;
  const char* baseline;
  double maxRatio;
  double maxExcess;
};
constexpr RelativeBound kRelativeBounds[] = {
    {"prt_macbeth", "prt-spectral", "prt-reference-5nm", 1.0, 0.05},
    {"prt_metamers", "prt-spectral", "prt-reference-5nm", 1.0, 0.05},
    {"prt_sky", "prt-spectral", "prt-reference-5nm", 1.0, 0.05},
    {"reef_", "jakob-hanika-16-1frame-optimised", "rgb", 0.5, 0.0},
};

struct Result {
  std::string scene, mode;
  imaging::DifferenceStats stats;  // against the direct-lighting (single-scattering) reference
  double meanVsGlobal = std::numeric_limits<double>::quiet_NaN();  // reef: vs multiple scattering
};

struct Sizes {
  int width, height, spheresSpp, reefSpp, reefGlobalSpp;
  int nebulaPixels;  // the most a side: the nebulae's CPU reference is most of their cost
};

constexpr double kHeatScale = 5.0;  // ΔE00 at the top of the heat maps and histograms

// One experiment: a scene's references and every mode of the rasteriser compared with them.
class Experiment {
 public:
  Experiment(const std::filesystem::path& output, const Sizes& sizes, ProgressBar& bar, std::size_t total)
      : mOutput(output), mSizes(sizes), mBar(bar), mTotal(total) {}

  // Renders and compares `scene` as `name` in `modes`. whiteFromReference: set the exposure so
  // that the reference's mean luminance is middle grey (0.18 of white) instead of the scene
  // camera's. A mode with a scene override renders `withSet(override)` instead.
  void run(const Scene& scene, const std::string& name, bool whiteFromReference, int spp, int globalSpp,
           std::span<const Mode> modes, const std::function<Scene(const char* set)>& withSet,
           std::vector<Result>& results) {
    const RgbToSpectrumTable& table = upsamplingTable(scene);
    reference::ReferenceSettings rs;
    rs.width = mSizes.width;
    rs.height = mSizes.height;
    rs.samplesPerPixel = spp;
    rs.filter = reference::PixelFilter::Centre;
    imaging::FloatImage direct = reference::renderReference(scene, table, rs).tristimulus;
    step();
    double white = render::displayWhiteLuminance(scene.camera.ev100);
    if (whiteFromReference) {
      double sum = 0.0;
      for (std::size_t i = 0; i < direct.pixelCount(); ++i) sum += direct.pixels[3 * i + 1];
      white = std::max(sum / static_cast<double>(direct.pixelCount()) / 0.18, 1e-6);
    }
    const float ev100 = static_cast<float>(std::log2(white / 1.2));
    imaging::FloatImage global;
    if (globalSpp > 0) {
      rs.samplesPerPixel = globalSpp;
      rs.transport = reference::LightTransport::Global;
      global = reference::renderReference(scene, table, rs).tristimulus;
      writeImages(global, fmt::format("{}_reference_global", name), ev100, white);
      step();
    }
    writeImages(direct, fmt::format("{}_reference", name), ev100, white);

    render::FrameSettings base;
    base.width = mSizes.width;
    base.height = mSizes.height;
    base.display.dither = false;
    base.display.ev100 = ev100;
    std::optional<render::Renderer> shared;  // one renderer, its settings changed per mode
    for (const Mode& m : modes) {
      render::FrameSettings settings = base;
      settings.mode = m.mode;
      settings.sampling.count = m.wavelengths;
      settings.sampling.strategy = m.strategy;
      std::optional<Scene> variant;
      std::optional<render::Renderer> own;
      if (m.set) {
        PRISM_CHECK(withSet);
        variant.emplace(withSet(m.set));
        own.emplace(*variant, table, settings);
      }
      if (!own && !shared) shared.emplace(scene, table, base);
      render::Renderer& renderer = own ? *own : *shared;
      renderer.setSettings(settings);
      auto input = [&](const imaging::FloatImage& i) {
        return imaging::linearInput(i, imaging::ColourMeaning::Xyz, white);
      };
      imaging::DifferenceStats sum, sumVsGlobal;
      for (int k = 0; k < m.singles; ++k) {
        renderer.resetAccumulation();
        for (int f = 0; f < m.frames; ++f) renderer.renderFrame();
        imaging::FloatImage image(mSizes.width, mSizes.height, 3);
        image.pixels = renderer.readMeanTristimulus();
        imaging::DifferenceOptions options;
        options.keepMap = k == 0;
        imaging::ImageDifference d = imaging::compareImages(input(direct), input(image), options);
        addStats(sum, d.stats);
        if (globalSpp > 0) addStats(sumVsGlobal, imaging::compareImages(input(global), input(image)).stats);
        if (k > 0) continue;  // the images shown are the first frame's
        displayImage(image, settings.display, observer(settings.observer), ev100).write(mOutput / fmt::format("{}_{}.png", name, m.name));
        writePictures(d.deltaEMap, fmt::format("{}_{}", name, m.name));
      }
      Result r{name, m.name, averaged(sum, m.singles)};
      if (globalSpp > 0) r.meanVsGlobal = averaged(sumVsGlobal, m.singles).meanDeltaE;
      results.push_back(r);
      step();
    }
  }

  // A nebula's methods against its reference (validate_nebula.h).
  void runNebula(const NebulaExperiment& nebula, const std::filesystem::path& sceneDir, std::vector<Result>& results) {
    for (NebulaMethodDifference& m : runNebulaExperiment(nebula, sceneDir, mSizes.nebulaPixels, mOutput, [this] { step(); })) {
      writePictures(m.difference.deltaEMap, fmt::format("{}_{}", nebula.name, m.mode));
      results.push_back({nebula.name, m.mode, m.difference.stats});
    }
  }

 private:
  void step() { mBar.update(++mDone, mTotal); }
  // STEM_heatmap.png and STEM_histogram.png of a ΔE00 map.
  void writePictures(const imaging::FloatImage& deltaE, const std::string& stem) {
    imaging::heatMap(deltaE, {.maxDeltaE = kHeatScale, .legend = true}).write(mOutput / (stem + "_heatmap.png"));
    imaging::HistogramOptions histogram;
    histogram.maxDeltaE = kHeatScale;
    imaging::deltaEHistogram(deltaE, histogram).write(mOutput / (stem + "_histogram.png"));
  }
  void writeImages(const imaging::FloatImage& image, const std::string& stem, float ev100, double white) {
    render::DisplaySettings display;
    display.ev100 = ev100;
    displayImage(image, display, observer("cie1931"), ev100).write(mOutput / (stem + ".png"));
    imaging::writeExr(mOutput / (stem + ".exr"), image, {.colour = imaging::ColourMeaning::Xyz, .displayWhite = white});
  }

  const std::filesystem::path& mOutput;
  Sizes mSizes;
  ProgressBar& mBar;
  std::size_t mTotal;
  std::size_t mDone = 0;
};

std::string reefName(float depthM) { return fmt::format("reef_{:g}m", depthM); }

std::string resultTable(const std::vector<Result>& results) {
  std::ostringstream out;
  out << fmt::format("{:<18} {:<34} {:>9} {:>8} {:>8} {:>8} {:>8} {:>11}\n", "scene", "mode", "mean ΔE00",
                     "median", "p95", "max", "MAE 8b", "vs global");
  for (const Result& r : results) {
    out << fmt::format("{:<18} {:<34} {:>9.3f} {:>8.3f} {:>8.3f} {:>8.2f} {:>8.3f} {:>11}\n", r.scene, r.mode,
                       r.stats.meanDeltaE, r.stats.medianDeltaE, r.stats.p95DeltaE, r.stats.maxDeltaE,
                       r.stats.mae8, std::isnan(r.meanVsGlobal) ? "" : fmt::format("{:.3f}", r.meanVsGlobal));
  }
  return out.str();
}

std::string indexHtml(const std::vector<Result>& results, const std::vector<std::string>& failures,
                      const Sizes& sizes) {
  HtmlPage page("Prism validation");
  page.paragraph(fmt::format(
      "The rasteriser against the reference path tracer at the pixel centres, 4 hero wavelengths a path, "
      "{}×{}: direct lighting (single scattering under water; {} paths per pixel for the spheres, {} for the "
      "reef) and, for the reef, multiple scattering ({} paths; the last column). ΔE00 is CIEDE2000 in XYZ "
      "before the display transform relative to the exposure's white (the scene camera's for the spheres; "
      "for the reef, the one that makes the reference's mean luminance middle grey); MAE is on 8-bit sRGB "
      "after it. Heat maps and histograms span ΔE00 0–{}. The single frames of a strategy whose wavelengths "
      "move between frames (importance, lights) are {} frames in a row, each alone: their statistics are "
      "averaged, their images are the first's. Spectral PRT's scenes are lit by their environments, which the path "
      "tracer traces before any projection (direct lighting, {} paths per pixel): the difference of the 5 nm "
      "mode is the SH-5 band limit and the path tracer's noise, what the spectral mode (m = 8) adds to it is its "
      "basis's, RGB-PRT's its three channels'. The nebulae are rendered by each method of the GPU marcher against "
      "the CPU's reference (the paper's double integration over wavelength), ΔE00 as the screen shows them before "
      "its clip: natural colour as XYZ relative to Y's white level (its 99.5th percentile), the Hubble palette as "
      "linear sRGB after each channel's stretch to its own, both by the reference's levels.",
      sizes.width, sizes.height, sizes.spheresSpp, sizes.reefSpp, sizes.reefGlobalSpp, kHeatScale, kSingleFrames,
      sizes.spheresSpp));
  if (failures.empty()) {
    page.paragraph("Every bound holds.");
  } else {
    page.paragraph("Broken bounds:", "fail");
    page.list(failures, "fail");
  }
  std::vector<std::vector<std::string>> rows;
  for (const Result& r : results) {
    rows.push_back({htmlEscape(r.scene), htmlEscape(r.mode), fmt::format("{:.3f}", r.stats.meanDeltaE),
                    fmt::format("{:.3f}", r.stats.medianDeltaE), fmt::format("{:.3f}", r.stats.p95DeltaE),
                    fmt::format("{:.2f}", r.stats.maxDeltaE), fmt::format("{:.3f}", r.stats.mae8),
                    std::isnan(r.meanVsGlobal) ? "" : fmt::format("{:.3f}", r.meanVsGlobal)});
  }
  page.table({"scene", "mode", "mean ΔE00", "median", "p95", "max", "MAE", "mean ΔE00 vs multiple scattering"}, rows);
  auto section = [&](const std::string& name, const std::string& title, bool global, const std::vector<std::string>& modes) {
    if (std::none_of(results.begin(), results.end(), [&](const Result& r) { return r.scene == name; })) return;  // --only
    page.beginSection("", title);
    page.figure({{name + "_reference.png", "reference"}}, global ? "reference (single scattering)" : "reference");
    if (global) page.figure({{name + "_reference_global.png", "multiple scattering"}}, "reference (multiple scattering)");
    page.lineBreak();
    for (const std::string& m : modes) {
      const std::string stem = fmt::format("{}_{}", name, m);
      page.figure({{stem + ".png", m}, {stem + "_heatmap.png", "ΔE00 heat map"},
                   {stem + "_histogram.png", "ΔE00 histogram", 320}}, m);
    }
    page.endSection();
  };
  auto names = [](std::span<const Mode> modes) {
    std::vector<std::string> v;
    for (const Mode& m : modes) v.push_back(m.name);
    return v;
  };
  for (const SphereScene& e : kSphereScenes) section(e.name, fmt::format("{} — under {}", e.name, e.light), false, names(kModes));
  for (float depth : kReefDepthsM) {
    section(reefName(depth), fmt::format("the reef, Jerlov I, camera {:g} m deep", depth), true, names(kModes));
  }
  for (const PrtScene& p : kPrtScenes)
    section(p.name, fmt::format("{} — spectral PRT under {}", p.name, p.environment), false, names(kPrtModes));
  std::vector<std::string> nebulaModes;
  for (nebula::Method m : kNebulaMethods) nebulaModes.push_back(nebula::methodName(m));
  for (const NebulaExperiment& n : kNebulaExperiments)
    section(n.name, fmt::format("{} — a spectral nebula, {}", n.name,
                                std::string(n.filters) == "hubble" ? "the Hubble palette" : "natural colour (CIE 1931)"),
            false, nebulaModes);
  return page.html();
}

nlohmann::json resultJson(const Result& r) {
  nlohmann::json row = {{"scene", r.scene}, {"mode", r.mode}, {"mean_delta_e", r.stats.meanDeltaE},
                        {"median_delta_e", r.stats.medianDeltaE}, {"p95_delta_e", r.stats.p95DeltaE},
                        {"max_delta_e", r.stats.maxDeltaE}, {"mae_8bit", r.stats.mae8},
                        {"relative_error", r.stats.relativeError}};
  if (!std::isnan(r.meanVsGlobal)) row[kResultVsMultipleScattering] = r.meanVsGlobal;
  return row;
}

// A row of a part (validate_parts.h, checked by readValidatePart) as its Result: what the report
// and the bounds read of it.
Result resultFromJson(const nlohmann::json& row) {
  Result r;
  r.scene = row.at("scene").get<std::string>();
  r.mode = row.at("mode").get<std::string>();
  // A statistic over a pixel that is not finite is +∞, which JSON writes as null.
  auto statistic = [&row](const char* key) {
    const nlohmann::json& v = row.at(key);
    return v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
  };
  r.stats.meanDeltaE = statistic("mean_delta_e");
  r.stats.medianDeltaE = statistic("median_delta_e");
  r.stats.p95DeltaE = statistic("p95_delta_e");
  r.stats.maxDeltaE = statistic("max_delta_e");
  r.stats.mae8 = statistic("mae_8bit");
  r.stats.relativeError = statistic("relative_error");
  if (row.contains(kResultVsMultipleScattering)) r.meanVsGlobal = statistic(kResultVsMultipleScattering);
  return r;
}

nlohmann::json sizesJson(const Sizes& sizes) {
  return {{"width", sizes.width}, {"height", sizes.height},
          {"reference_paths_per_pixel", {{"spheres", sizes.spheresSpp}, {"reef", sizes.reefSpp},
                                         {"reef_multiple_scattering", sizes.reefGlobalSpp}}},
          {"nebula_pixels", sizes.nebulaPixels}};
}

nlohmann::json toJson(const std::vector<Result>& results, const std::vector<std::string>& failures,
                      const Sizes& sizes) {
  nlohmann::json rows = nlohmann::json::array();
  for (const Result& r : results) rows.push_back(resultJson(r));
  nlohmann::json json = sizesJson(sizes);
  json["results"] = rows;
  json["failures"] = failures;
  return json;
}

// The experiments, in the order of the report: the sphere scenes, the reef's depths, PRT's scenes,
// the nebulae.
constexpr std::size_t kReefBegin = std::size(kSphereScenes);
constexpr std::size_t kPrtBegin = kReefBegin + std::size(kReefDepthsM);
constexpr std::size_t kNebulaBegin = kPrtBegin + std::size(kPrtScenes);
constexpr std::size_t kExperiments = kNebulaBegin + std::size(kNebulaExperiments);
std::string experimentName(std::size_t e) {
  if (e < kReefBegin) return kSphereScenes[e].name;
  if (e < kPrtBegin) return reefName(kReefDepthsM[e - kReefBegin]);
  if (e < kNebulaBegin) return kPrtScenes[e - kPrtBegin].name;
  return kNebulaExperiments[e - kNebulaBegin].name;
}
// Progress steps: the reference (the reef's two), then one per mode.
std::size_t experimentSteps(std::size_t e) {
  if (e < kReefBegin) return 1 + std::size(kModes);
  if (e < kPrtBegin) return 2 + std::size(kModes);
  if (e < kNebulaBegin) return 1 + std::size(kPrtModes);
  return 1 + std::size(kNebulaMethods);
}

// results.json and index.html of all the experiments, the table (or the JSON) printed and the
// bounds checked: 0 when every bound holds.
int report(const ValidateOptions& o, const Sizes& sizes, const std::vector<Result>& results) {
  std::vector<std::string> failures;
  for (const Bound& b : kBounds) {
    for (const Result& r : results) {
      if (r.scene == b.scene && r.mode == b.mode && !(r.stats.meanDeltaE <= b.maxMeanDeltaE)) {
        failures.push_back(fmt::format("{} {}: mean ΔE00 {:.3f} > {}", b.scene, b.mode, r.stats.meanDeltaE,
                                       b.maxMeanDeltaE));
      }
    }
  }
  for (const NebulaBound& b : kNebulaBounds) {
    for (const Result& r : results) {
      if (r.mode != nebula::methodName(b.method)) continue;
      if (!(r.stats.meanDeltaE <= b.maxMeanDeltaE))
        failures.push_back(fmt::format("{} {}: mean ΔE00 {:.3f} > {}", r.scene, r.mode, r.stats.meanDeltaE, b.maxMeanDeltaE));
      if (!(r.stats.maxDeltaE <= b.maxMaxDeltaE))
        failures.push_back(fmt::format("{} {}: max ΔE00 {:.3f} > {}", r.scene, r.mode, r.stats.maxDeltaE, b.maxMaxDeltaE));
    }
  }
  for (const RelativeBound& b : kRelativeBounds) {
    for (const Result& mode : results) {
      if (!mode.scene.starts_with(b.scenePrefix) || mode.mode != b.mode) continue;
      for (const Result& baseline : results) {
        if (baseline.scene != mode.scene || baseline.mode != b.baseline) continue;
        if (!(mode.stats.meanDeltaE <= b.maxRatio * baseline.stats.meanDeltaE + b.maxExcess))
          failures.push_back(fmt::format("{} {}: mean ΔE00 {:.3f} > {:g} × {}'s {:.3f} + {:g}", mode.scene, mode.mode,
                                         mode.stats.meanDeltaE, b.maxRatio, b.baseline, baseline.stats.meanDeltaE,
                                         b.maxExcess));
      }
    }
  }
  nlohmann::json json = toJson(results, failures, sizes);
  writeFileAtomically(o.output / "results.json", json.dump(2) + "\n");
  writeFileAtomically(o.output / "index.html", indexHtml(results, failures, sizes));
  if (o.json) {
    fmt::print("{}\n", json.dump(2));
  } else {
    fmt::print("{}", resultTable(results));
    fmt::print("wrote {}\n", (o.output / "index.html").string());
  }
  for (const std::string& f : failures) fmt::print(stderr, "prism: validate: bound broken: {}\n", f);
  return failures.empty() ? 0 : 1;
}

// The experiments `only` names, in the report's order (every one when it is empty).
std::vector<std::size_t> chosenExperiments(const std::vector<std::string>& only) {
  std::vector<std::size_t> chosen;
  std::vector<std::string> all;
  for (std::size_t e = 0; e < kExperiments; ++e) all.push_back(experimentName(e));
  for (const std::string& name : only) {
    if (std::find(all.begin(), all.end(), name) == all.end())
      throw Error(fmt::format("--only: no experiment \"{}\" ({})", name, fmt::join(all, ", ")));
  }
  for (std::size_t e = 0; e < kExperiments; ++e) {
    if (only.empty() || std::find(only.begin(), only.end(), all[e]) != only.end()) chosen.push_back(e);
  }
  return chosen;
}

}  // namespace

int validateExperimentCount(const std::vector<std::string>& only) {
  return static_cast<int>(chosenExperiments(only).size());
}

int runValidate(const ValidateOptions& o) {
  const Sizes sizes = o.quick ? Sizes{240, 135, 64, 32, 8, 64} : Sizes{640, 360, 256, 128, 64, 360};
  const std::filesystem::path sceneDir = o.scenes.empty() ? exampleSceneDirectory() : o.scenes;
  const nlohmann::json identity = {{"sizes", sizesJson(sizes)}, {"scenes", std::filesystem::absolute(sceneDir).string()}};
  const std::vector<std::size_t> chosen = chosenExperiments(o.only);
  const int count = static_cast<int>(chosen.size());
  std::vector<std::string> names;
  for (std::size_t e : chosen) names.push_back(experimentName(e));

  if (o.collect) {
    std::vector<Result> results;
    for (const nlohmann::json& row : collectValidateParts(o.output, identity, names, o.tasks)) results.push_back(resultFromJson(row));
    return report(o, sizes, results);
  }
  setAllThreads(o.threads);  // every pass's "all threads": the images do not depend on it
  IndexRange share{0, count};
  std::filesystem::path partPath;
  if (!o.task.empty()) {
    TaskIndex task = parseTaskIndex(o.task, "--task");
    if (task.count > count)
      throw Error(fmt::format("--task {}: at most {} tasks, one per experiment", o.task, count));
    share = shareOf(task, count);
    partPath = validatePartPath(o.output, task);
    try {
      ValidatePart existing = readValidatePart(partPath);
      if (existing.identity == identity &&
          existing.experiments == std::vector<std::string>(names.begin() + share.begin, names.begin() + share.end)) {
        fmt::print("{}: complete, skipped\n", partPath.string());
        return 0;
      }
    } catch (const Error&) {
      // Missing or unreadable: this task's work is still to do.
    }
  }

  std::filesystem::create_directories(o.output);
  gpu::HeadlessContext context;
  std::vector<Result> results;
  ProgressBar bar("validate");
  std::size_t total = 0;
  for (int e = share.begin; e < share.end; ++e) total += experimentSteps(chosen[static_cast<std::size_t>(e)]);
  Experiment experiment(o.output, sizes, bar, total);
  auto load = [&](const std::string& name, const std::vector<std::string>& sets) {
    return loadScene(sceneDir / (name + ".json"), sets);
  };
  for (int e = share.begin; e < share.end; ++e) {
    const std::size_t k = chosen[static_cast<std::size_t>(e)];
    if (k < std::size(kSphereScenes)) {
      const SphereScene& sphere = kSphereScenes[k];
      std::vector<std::string> sets;
      if (sphere.set) sets.push_back(sphere.set);
      experiment.run(load(sphere.scene, sets), sphere.name, false, sizes.spheresSpp, 0, kModes, {}, results);
    } else if (k < kPrtBegin) {
      const float depth = kReefDepthsM[k - kReefBegin];
      Scene reef = load("reef", {"water.type=I", fmt::format("water.depth={:g}", depth)});
      experiment.run(reef, reefName(depth), true, sizes.reefSpp, sizes.reefGlobalSpp, kModes, {}, results);
    } else if (k < kNebulaBegin) {
      const char* name = kPrtScenes[k - kPrtBegin].name;
      Scene prt = load(name, {});
      precomputeTechniques(prt);  // the transfer, from its cache or baked (shared by the modes)
      experiment.run(prt, name, false, sizes.spheresSpp, 0, kPrtModes,
                     [&](const char* set) { return load(name, {set}); }, results);
    } else {
      experiment.runNebula(kNebulaExperiments[k - kNebulaBegin], sceneDir, results);
    }
  }
  if (partPath.empty()) return report(o, sizes, results);

  ValidatePart part{identity, std::vector<std::string>(names.begin() + share.begin, names.begin() + share.end),
                    nlohmann::json::array()};
  for (const Result& r : results) part.results.push_back(resultJson(r));
  writeValidatePart(partPath, part);
  fmt::print("wrote {} ({} of {} experiments)\n", partPath.string(), share.size(), count);
  return 0;
}

}  // namespace prism::harness

#include "app/nebula_commands.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/input_file.h"
#include "core/json_schema.h"
#include "gpu/headless_context.h"
#include "gpu/timer_query.h"
#include "core/atomic_file.h"
#include "core/file_extension.h"
#include "harness/log_plot.h"
#include "harness/nebula_display.h"
#include "harness/progress_bar.h"
#include "imaging/exr_file.h"
#include "imaging/float_image.h"
#include "scene/scene_loader.h"
#include "techniques/nebula/nebula_basis.h"
#include "techniques/nebula/nebula_basis_coverage.h"
#include "techniques/nebula/nebula_light_warnings.h"
#include "techniques/nebula/gpu/nebula_gpu_marcher.h"
#include "techniques/nebula/nebula_scene.h"
#include "techniques/nebula/nebula_section.h"

namespace prism::app {
namespace {

// An integer option within lo..hi, the message naming the option as the user wrote it
// (nebula::validate checks the same settings again, by the names a library knows).
void requireWithin(const char* option, std::optional<int> value, int lo, int hi) {
  if (value && (*value < lo || *value > hi)) throw Error(fmt::format("{}: {} is not within {}..{}", option, *value, lo, hi));
}

// A plot's file, checked before the work: an .svg where a file can be written (none: nothing).
void requirePlotFile(const std::filesystem::path& plot) {
  if (plot.empty()) return;
  requireExtension(plot, ".svg", "--plot", "plot");
  requireWritable(plot);
}

// A density's progress, its bar shown at its first report (none when nothing is generated).
nebula::DensityProgress densityBar(std::optional<harness::ProgressBar>& bar) {
  return [&bar](std::size_t done, std::size_t total) {
    if (!bar) bar.emplace("nebula: density noise");
    bar->update(done, total);
  };
}

// A scene file's noise generated with a progress bar (512³: 15 s on 2 cores, the file written), once the
// command has checked what it could without it.
nebula::NebulaScene generateWithProgress(nebula::NebulaSceneFile file, unsigned threads) {
  std::optional<harness::ProgressBar> bar;
  return nebula::generateDensity(std::move(file), threads, densityBar(bar));
}

void requireFilterSet(const std::string& filters) {
  if (!filters.empty() && filters != "hubble" && filters != "cie1931")
    throw Error(fmt::format("--filters: '{}' is not hubble or cie1931", excerpt(filters)));
}

// --filters over the scene's own set. The scene's passband edits are per channel, so they move
// the other set's passbands: one that leaves nothing of its passband is the scene's error, said
// before the work (it came after the precomputation, naming neither the scene nor --filters).
void overrideFilters(nebula::NebulaSceneFile& file, const std::filesystem::path& scene, const std::string& filters) {
  if (filters.empty()) return;
  try {
    nebula::editedFilterSet(nebula::filterSet(filters), file.scene.model.passbands);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: /nebula/passbands: under --filters {}: {}", scene.string(), filters, e.what()));
  }
  file.scene.model.filters = filters;
}

}  // namespace

void runNebulaBasis(const NebulaBasisOptions& o) {
  // Each option named with its value. NaN fails every comparison, so each bound is written to be
  // true of a good value.
  if (!(o.lambda0Um >= 0.0 && o.lambda1Um > o.lambda0Um && o.lambda1Um <= 100.0))
    throw Error(fmt::format("--domain {:g},{:g}: need 0 ≤ LO < HI ≤ 100 µm", o.lambda0Um, o.lambda1Um));
  if (o.count < 1 || o.count > 8) throw Error(fmt::format("--count {}: need 1 to 8 elements", o.count));
  if (!(o.maxDepthUm > 0.0 && o.maxDepthUm <= 1000.0))
    throw Error(fmt::format("--max-depth {:g}: need a depth within (0, 1000] µm", o.maxDepthUm));
  if (!(o.maxExponentUm > 0.0 && o.maxExponentUm <= 1000.0))
    throw Error(fmt::format("--max-exponent {:g}: need an exponent within (0, 1000] µm", o.maxExponentUm));
  if (!(o.spacingUm >= 0.0 && o.spacingUm <= o.maxExponentUm))
    throw Error(fmt::format("--spacing {:g}: need a spacing within [0, --max-exponent] = [0, {:g}] µm", o.spacingUm,
                            o.maxExponentUm));
  requirePlotFile(o.plotFile);
  nebula::ExpBasis b = nebula::findExpBasis(o.lambda0Um, o.lambda1Um, o.maxDepthUm, o.maxExponentUm, o.count,
                                            o.spacingUm, /*orthonormalise=*/false);
  if (static_cast<int>(b.a.size()) < o.count)
    throw Error(fmt::format("nebula basis: only {} of {} elements found: no other exponent within 0–{:g} µm keeps the "
                            "spacing of {:g} µm and adds a new direction", b.a.size(), o.count, o.maxExponentUm, o.spacingUm));
  if (o.json) {
    fmt::print("{{\"lambda_um\": [{}, {}], \"max_depth_um\": {}, \"spacing_um\": {}, \"elements\": [", o.lambda0Um,
               o.lambda1Um, o.maxDepthUm, o.spacingUm);
    for (std::size_t k = 0; k < b.a.size(); ++k)
      fmt::print("{}{{\"a_um\": {:.4f}, \"max_relative_error\": {:.4e}}}", k ? ", " : "", b.a[k], b.maxError[k]);
    fmt::print("]}}\n");
  } else {
    fmt::print("greedy exp(-a/lambda) basis on [{}, {}] um, family exp(-g/lambda) for g in [0, {}] um, "
               "exponents in [0, {}] um, minimum spacing {} um\n",
               o.lambda0Um, o.lambda1Um, o.maxDepthUm, o.maxExponentUm, o.spacingUm);
    fmt::print("{:>8} {:>10} {:>22}\n", "element", "a (um)", "max relative L2 error");
    for (std::size_t k = 0; k < b.a.size(); ++k) fmt::print("{:>8} {:>10.4f} {:>22.4e}\n", k + 1, b.a[k], b.maxError[k]);
  }
  if (!o.plotFile.empty()) {
    harness::LogPlot plot;
    plot.title = fmt::format("greedy exp(−a/λ) basis on [{}, {}] µm, g ≤ {} µm, spacing ≥ {} µm", o.lambda0Um, o.lambda1Um,
                             o.maxDepthUm, o.spacingUm);
    plot.xLabel = "elements";
    plot.yLabel = "worst relative L2 projection error";
    harness::LogPlotLine line{"worst error", "#1f77b4", {}};
    for (std::size_t k = 0; k < b.a.size(); ++k) {
      plot.xTicks.push_back(static_cast<double>(k + 1));
      line.points.emplace_back(static_cast<double>(k + 1), b.maxError[k]);
      plot.notes.push_back(fmt::format("a{} = {:.4f} µm", k + 1, b.a[k]));
    }
    plot.lines.push_back(std::move(line));
    writeFileAtomically(o.plotFile, harness::logPlotSvg(plot));
    if (!o.json) fmt::print("wrote {}\n", o.plotFile.string());
  }
}

namespace {

// Error unless an asked basis depth is within (0, kMaxBasisDepthUm].
void requireBasisDepth(const std::optional<double>& basisDepthUm) {
  if (basisDepthUm && !(*basisDepthUm > 0.0 && *basisDepthUm <= nebula::kMaxBasisDepthUm))
    throw Error(fmt::format("--basis-depth: {:g} is not within (0, {:g}] µm", *basisDepthUm, nebula::kMaxBasisDepthUm));
}

// On stderr, what the scene's grid, light and view, and the march and basis of `s`, would get wrong
// or leave black (nebula_density.h, nebula_render.h, nebula_basis_coverage.h); `deeperBasisFormat`
// names the options that fit a deeper basis.
void printWarnings(const nebula::NebulaRenderer& renderer, const nebula::BasisCoverage& coverage,
                   const nebula::RenderSettings& s, std::string_view deeperBasisFormat) {
  for (const std::string& warning : {nebula::coarseGridWarning(renderer.model().density),
                                     nebula::emptyGridWarning(renderer.model().density),
                                     nebula::unlitLinesWarning(renderer.model()), nebula::darkNebulaWarning(renderer),
                                     nebula::outOfViewWarning(coverage),
                                     nebula::stepThicknessWarning(coverage, s, "--steps {:.0f}"),
                                     nebula::basisCoverageWarning(coverage, s, deeperBasisFormat)})
    if (!warning.empty()) fmt::print(stderr, "prism: warning: {}\n", warning);
}

// What a black reference's error (maxRelativeError's NaN: no pixel compared) is printed as.
constexpr std::string_view kBlackReference = "none: the reference is black, no pixel holds light";

}  // namespace

void runNebulaSweep(const NebulaSweepOptions& o) {
  requireWithin("--max-basis", o.maxBasis, 1, nebula::kMaxBasisSize);
  requireWithin("--size", o.size, 1, nebula::kMaxImageSide);
  requireWithin("--steps", o.steps, 1, nebula::kMaxSteps);
  requirePlotFile(o.plotFile);
  requireOtherFile(o.plotFile, o.scene, "the scene file");
  requireBasisDepth(o.basisDepthUm);
  nebula::RenderSettings s;
  s.steps = o.steps.value_or(s.steps);
  s.basisMaxDepthUm = o.basisDepthUm.value_or(s.basisMaxDepthUm);
  nebula::validate(s);
  requireFilterSet(o.filters);
  nebula::NebulaSceneFile file = nebula::readNebulaScene(o.scene);
  requireOtherFile(o.plotFile, file.source.file, "the scene's density file");
  overrideFilters(file, o.scene, o.filters);
  nebula::NebulaScene scene = generateWithProgress(std::move(file), o.threads);
  nebula::NebulaCamera& camera = scene.model.camera;
  if (o.size) nebula::scaleImage(camera, *o.size);
  s.steps = o.steps.value_or(scene.steps);
  s.emissionLines = !o.noLines;
  s.threads = o.threads;
  std::vector<double> errors;
  nebula::NebulaImage reference;
  {
    // By rows rendered: the reference's, the longest by far, moved the bar by one step in
    // maxBasis + 1, and it stood at 0 % until it was done.
    harness::ProgressBar bar("nebula sweep: the reference, then projection by basis size");
    const std::size_t rows = static_cast<std::size_t>(camera.height);
    const std::size_t total = (static_cast<std::size_t>(o.maxBasis) + 1) * rows;
    std::size_t before = 0;  // rows of the renders done
    auto progress = [&](std::size_t done, std::size_t) { bar.update(before + done, total); };
    for (int n = 1; n <= o.maxBasis; ++n) {
      s.basisSize = n;
      nebula::NebulaRenderer renderer(scene.model, s);
      if (n == 1) {
        // What `nebula render` says of the scene, before the sweep's renders: a sweep whose every
        // size missed by far (thick dust beyond the basis's depth) said nothing of why.
        s.method = nebula::Method::Projection;
        const nebula::BasisCoverage coverage = nebula::basisCoverage(renderer, s, renderer.model().camera);
        printWarnings(renderer, coverage, s, "--basis-depth {:.0f} --max-basis 6");
        s.method = nebula::Method::Reference;
        reference = renderer.render(s, progress);
        before += rows;
      }
      s.method = nebula::Method::Projection;
      errors.push_back(nebula::maxRelativeError(renderer.render(s, progress), reference));  // NaN: JSON's null
      before += rows;
    }
  }
  const std::string filters = scene.model.filters;
  if (o.json) {
    fmt::print("{}\n", nlohmann::json{{"scene", o.scene.string()},  // escaped: a path may hold any character
                                      {"filters", filters},
                                      {"width", camera.width},
                                      {"height", camera.height},
                                      {"steps", s.steps},
                                      {"max_relative_error", errors}}
                           .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));  // a path's bytes
  } else {
    fmt::print("projection (CPU, float) against the reference: {}, {}x{}, {} steps, {} star(s)\n", filters,
               camera.width, camera.height, s.steps, scene.model.stars.size());
    fmt::print("{:>8} {:>26}\n", "elements", "max relative error per pixel");
    for (std::size_t k = 0; k < errors.size(); ++k)
      if (std::isnan(errors[k])) fmt::print("{:>8} {}\n", k + 1, kBlackReference);
      else fmt::print("{:>8} {:>25.4g}%\n", k + 1, 100.0 * errors[k]);
  }
  if (!o.plotFile.empty()) {
    harness::LogPlot plot;
    plot.title = fmt::format("{}: projection against the reference ({}, {}x{})", o.scene.filename().string(), filters,
                             camera.width, camera.height);
    plot.xLabel = "basis elements";
    plot.yLabel = "max relative error per pixel";
    harness::LogPlotLine line{"projection, float", "#d62728", {}};
    for (std::size_t k = 0; k < errors.size(); ++k) {
      plot.xTicks.push_back(static_cast<double>(k + 1));
      if (!std::isnan(errors[k])) line.points.emplace_back(static_cast<double>(k + 1), errors[k]);
    }
    plot.lines.push_back(std::move(line));
    plot.levels.push_back({"the issue's bound, 2 %", "#888", 0.02, /*dashed=*/false, /*thick=*/true});
    writeFileAtomically(o.plotFile, harness::logPlotSvg(plot));
    if (!o.json) fmt::print("wrote {}\n", o.plotFile.string());
  }
}

namespace {

void writeImage(const nebula::NebulaImage& image, const std::string& filters, const std::filesystem::path& out) {
  std::string ext = lowercaseExtension(out);
  bool hubble = filters == "hubble";
  if (ext == ".exr") {
    imaging::FloatImage f(image.width, image.height, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) f.pixels[i * 3 + static_cast<std::size_t>(c)] = image.pixels[i][c];
    imaging::ExrWriteOptions options;
    options.colour = hubble ? imaging::ColourMeaning::OtherRgb : imaging::ColourMeaning::Xyz;
    imaging::writeExr(out, f, options);
    return;
  }
  if (ext != ".png") throw Error(fmt::format("{}: the output must be .exr or .png", out.string()));
  harness::nebulaDisplayPng(image, hubble).write(out);
}

}  // namespace

void runNebulaRender(const NebulaRenderOptions& o) {
  requireWritable(o.output);  // first, so that an empty name is said to be one
  requireOtherFile(o.output, o.scene, "the scene file");
  if (lowercaseExtension(o.output) != ".exr" && lowercaseExtension(o.output) != ".png")
    throw Error(fmt::format("{}: the output must be .exr or .png", o.output.string()));
  nebula::Method method = nebula::methodFromName(o.method);
  requireWithin("--steps", o.steps, 1, nebula::kMaxSteps);
  requireWithin("--size", o.size, 1, nebula::kMaxImageSide);
  requireWithin("--basis", o.basisSize, 1, nebula::kMaxBasisSize);
  requireBasisDepth(o.basisDepthUm);
  requireWithin("--light-basis", o.lightBasisSize, 1, nebula::kMaxLightBasisSize);
  requireWithin("--reference-intervals", o.referenceIntervals, 2, nebula::kMaxReferenceIntervals);
  if (o.referenceIntervals && *o.referenceIntervals % 2 != 0)
    throw Error(fmt::format("--reference-intervals: {} is odd (Simpson's rule takes pairs)", *o.referenceIntervals));
  if (o.uniformSamples != 0 && (o.uniformSamples < 2 || o.uniformSamples > nebula::kMaxUniformSamples))
    throw Error(fmt::format("--uniform-samples: {} is not 0 (Simpson) or within 2..{}", o.uniformSamples,
                            nebula::kMaxUniformSamples));
  nebula::RenderSettings s;
  s.method = method;
  s.steps = o.steps.value_or(s.steps);
  s.basisSize = o.basisSize.value_or(s.basisSize);
  s.basisMaxDepthUm = o.basisDepthUm.value_or(s.basisMaxDepthUm);
  s.lightBasisSize = o.lightBasisSize.value_or(s.lightBasisSize);
  s.referenceIntervals = o.referenceIntervals.value_or(s.referenceIntervals);
  s.uniformSamples = o.uniformSamples;
  nebula::validate(s);
  if (o.compare && method == nebula::Method::Reference && o.uniformSamples == 0 &&
      2 * s.referenceIntervals > nebula::kMaxReferenceIntervals)
    throw Error(fmt::format("--compare: the reference at {} Simpson intervals has no finer one within {} to be compared "
                            "with", s.referenceIntervals, nebula::kMaxReferenceIntervals));
  if (o.uniformSamples != 0 && method != nebula::Method::Reference)
    throw Error(fmt::format("--uniform-samples {}: only with --method reference (the paper's baseline); {} samples no "
                            "wavelengths", o.uniformSamples, o.method));
  const bool onBasis = method == nebula::Method::Projection || method == nebula::Method::LightDensity;
  if (o.basisSize && !onBasis)
    throw Error(fmt::format("--basis {}: only with --method projection or light-density; {} projects on no basis",
                            *o.basisSize, o.method));
  if (o.basisDepthUm && !onBasis)
    throw Error(fmt::format("--basis-depth {:g}: only with --method projection or light-density; {} projects on no basis",
                            *o.basisDepthUm, o.method));
  if (o.lightBasisSize && method != nebula::Method::LightDensity)
    throw Error(fmt::format("--light-basis {}: only with --method light-density; {} has no light basis",
                            *o.lightBasisSize, o.method));
  if (o.referenceIntervals && !o.compare && !(method == nebula::Method::Reference && o.uniformSamples == 0))
    throw Error(fmt::format("--reference-intervals {}: only for the reference by Simpson's rule (--method reference "
                            "without --uniform-samples, or --compare)", *o.referenceIntervals));
  requireFilterSet(o.filters);
  nebula::NebulaSceneFile file = nebula::readNebulaScene(o.scene);
  requireOtherFile(o.output, file.source.file, "the scene's density file");
  if (o.size) nebula::scaleImage(file.scene.model.camera, *o.size);
  std::unique_ptr<gpu::HeadlessContext> context;
  if (o.gpu) {
    context = std::make_unique<gpu::HeadlessContext>();
    try {  // before any work, at the scene's stars as the renderer's scenes say it
      if (method != nebula::Method::LightDensity)
        nebula::requireGpuFits(file.densitySize().z, file.scene.model.stars.size());
    } catch (const Error& e) {
      throw Error(fmt::format("{}: /nebula/stars: {}; light-density's march reads none of them", o.scene.string(), e.what()));
    }
    const nebula::NebulaCamera& camera = file.scene.model.camera;
    const auto pixels = static_cast<std::size_t>(camera.width) * static_cast<std::size_t>(camera.height);
    if (method == nebula::Method::Projection)
      nebula::requireMomentsFit(file.scene.model.stars.size(), "stars", s.basisSize, pixels);
    if (method == nebula::Method::LightDensity)
      nebula::requireMomentsFit(static_cast<std::size_t>(s.lightBasisSize), "light functions", s.basisSize, pixels);
  }
  overrideFilters(file, o.scene, o.filters);
  nebula::NebulaScene scene = generateWithProgress(std::move(file), o.threads);
  s.steps = o.steps.value_or(scene.steps);
  s.emissionLines = !o.noLines;
  s.threads = o.threads;
  std::string filters = scene.model.filters;
  harness::ProgressBar bar(scene.model.ionisation ? "nebula: optical depth to each star, ionisation zones, bases"
                                                  : "nebula: optical depth to each star, bases");
  auto t0 = std::chrono::steady_clock::now();
  nebula::NebulaRenderer renderer(std::move(scene.model), s, [&bar](std::size_t d, std::size_t n) { bar.update(d, n); });
  auto t1 = std::chrono::steady_clock::now();
  const nebula::BasisCoverage coverage = nebula::basisCoverage(renderer, s, renderer.model().camera);
  printWarnings(renderer, coverage, s, "--basis-depth {:.0f} --basis 6");
  nebula::NebulaImage image;
  if (o.gpu) {
    nebula::NebulaGpuMarcher marcher(renderer);
    t1 = std::chrono::steady_clock::now();  // the upload and the shaders' compilation count as precomputation
    image = marcher.render(s);
  } else {
    harness::ProgressBar renderBar(fmt::format("nebula: {} on the CPU", nebula::methodName(method)));
    image = renderer.render(s, [&renderBar](std::size_t d, std::size_t n) { renderBar.update(d, n); });
  }
  auto t2 = std::chrono::steady_clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  fmt::print("{}{}: {}x{}, {} steps, {} star(s), precomputation {:.0f} ms, render {:.0f} ms\n", nebula::methodName(method),
             o.gpu ? " (GPU)" : "", image.width, image.height, s.steps, renderer.model().stars.size(), ms(t0, t1), ms(t1, t2));
  if (o.compare) {
    // The reference: Simpson at the given intervals; for a Simpson reference itself, at twice
    // as many (how far it is from converged).
    nebula::RenderSettings r = s;
    r.method = nebula::Method::Reference;
    r.uniformSamples = 0;
    std::string against = "the reference";
    if (method == nebula::Method::Reference && s.uniformSamples == 0) {
      r.referenceIntervals = 2 * s.referenceIntervals;
      against = fmt::format("the reference at {} Simpson intervals", r.referenceIntervals);
    }
    harness::ProgressBar referenceBar("nebula: " + against + ", to compare with");
    nebula::NebulaImage reference =
        renderer.render(r, [&referenceBar](std::size_t d, std::size_t n) { referenceBar.update(d, n); });
    const double worst = nebula::maxRelativeError(image, reference);
    const std::string error = std::isnan(worst) ? std::string(kBlackReference) : fmt::format("{:.4g}", worst);
    fmt::print("max relative error per pixel against {} (pixels ≥ 1 % of their channel's maximum): {}\n", against, error);
  }
  writeImage(image, filters, o.output);
  fmt::print("wrote {}\n", o.output.string());
}

namespace {

// Whether the file is a scene of the renderer (it has a camera), which may hold a nebula section.
bool isRendererScene(const std::filesystem::path& path) {
  requireInputFile(path, "a scene");
  const std::vector<unsigned char> bytes = schema::readBinaryFile(path);
  const nlohmann::json json =
      schema::parseJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path.string());
  return json.is_object() && json.contains("camera");
}

// The grid of a renderer scene's nebula section: its density file's, or its noise generated.
nebula::DensityGrid sectionDensity(const std::filesystem::path& scenePath, const std::filesystem::path& output) {
  const Scene scene = loadScene(scenePath);
  const auto* section = scene.techniques.find<nebula::NebulaSection>();
  if (!section) throw Error(fmt::format("{}: a scene of the renderer without a \"nebula\" section: no density to write", scenePath.string()));
  requireOtherFile(output, section->source.file, "the scene's density file");
  if (!section->source.noise) return section->fullModel().density;
  std::optional<harness::ProgressBar> bar;
  return nebula::generateFbm(*section->source.noise, 0, densityBar(bar));
}

}  // namespace

void runNebulaDensity(const std::filesystem::path& scenePath, const std::filesystem::path& output) {
  requireExtension(output, ".density", "-o", "density grid");
  requireOtherFile(output, scenePath, "the scene file");
  requireWritable(output);
  nebula::DensityGrid grid;
  if (isRendererScene(scenePath)) {
    grid = sectionDensity(scenePath, output);
  } else {
    nebula::NebulaSceneFile file = nebula::readNebulaScene(scenePath);
    requireOtherFile(output, file.source.file, "the scene's density file");
    grid = generateWithProgress(std::move(file), 0).model.density;
  }
  nebula::writeDensityFile(output, grid);
  fmt::print("wrote {} ({}x{}x{})\n", output.string(), grid.nx, grid.ny, grid.nz);
}

namespace {

double median(std::vector<double> times) {
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  return times[times.size() / 2];
}

// The median wall time of `repeats` calls, after one untimed call (first-use costs: the GPU's
// shader specialisation, the CPU's caches).
template <class F>
double medianMs(int repeats, F&& f) {
  f();
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return median(std::move(times));
}

// The same for the GPU's work of a march and its finish, by timestamps around them: what a frame
// spends on the nebula, without reading the image back (16 MB at 1024², which a frame never does
// and which the GPU's bus, not its march, would time).
double medianGpuMs(gpu::GpuTimer& timer, int repeats, nebula::NebulaGpuMarcher& marcher, const nebula::RenderSettings& s) {
  auto once = [&] {
    timer.beginFrame();
    marcher.march(s);
    marcher.finishOnGpu();
    timer.endFrame();
    return timer.resolve().front().second;  // "frame": beginFrame to endFrame
  };
  once();
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) times.push_back(once());
  return median(std::move(times));
}

}  // namespace

void runNebulaBench(const NebulaBenchOptions& o) {
  const int repeats = o.repeats;
  if (repeats < 1 || repeats > 1000) throw Error("nebula bench: --repeats must be 1 to 1000");
  if (o.size < 1 || o.size > nebula::kMaxImageSide)
    throw Error(fmt::format("nebula bench: --size must be 1 to {} pixels", nebula::kMaxImageSide));
  gpu::HeadlessContext context;
  gpu::GpuTimer timer;
  fmt::print("nebula bench: {0}x{0}, 100 steps, 32^3 cloud, Hubble palette, no lines; median of {1} runs (ms); "
             "{2}GPU: {3}, march + finish by timestamps (no read-back); filter edit: wall, refilter + finish\n",
             o.size, repeats, o.cpu ? "CPU one thread; " : "", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  fmt::print("{:>5} {:>14} {:>14} {:>14} {:>14} {:>16} {:>15} {:>15} {:>16}\n", "stars", "CPU ref (21λ)", "CPU projection",
             "GPU ref (21λ)", "GPU projection", "GPU light-dens.", "GPU ref/proj", "GPU ref/l-d", "GPU filter edit");
  for (int stars : {1, 6, 32}) {
    nebula::RenderSettings s;
    s.threads = 1;
    s.steps = 100;
    s.emissionLines = false;
    nebula::NebulaModel model = nebula::benchNebulaModel(stars);
    model.camera.width = model.camera.height = o.size;
    nebula::NebulaRenderer renderer(std::move(model), s);
    std::unique_ptr<nebula::NebulaRenderer> edited;  // the filter edits' renderers: they outlive the marcher
    nebula::NebulaGpuMarcher marcher(renderer);
    s.method = nebula::Method::Reference;
    s.uniformSamples = 7;  // 7 λ per channel, 21 a step: the paper's baseline (bench/nebula_bench.cpp)
    const double none = std::numeric_limits<double>::quiet_NaN();
    double reference = o.cpu ? medianMs(repeats, [&] { renderer.render(s); }) : none;
    double gpuReference = medianGpuMs(timer, repeats, marcher, s);
    s.method = nebula::Method::Projection;
    double cpuProjection = o.cpu ? medianMs(repeats, [&] { renderer.render(s); }) : none;
    double gpuProjection = medianGpuMs(timer, repeats, marcher, s);
    s.method = nebula::Method::LightDensity;
    double gpuLight = medianGpuMs(timer, repeats, marcher, s);
    // A passband moved after a projection march: refiltering the volume (CPU) and finishing the
    // same moments through the new weights (GPU), no march; alternately ±5 nm so each is an edit.
    s.method = nebula::Method::Projection;
    marcher.march(s);
    int edits = 0;
    double filterEdit = medianMs(repeats, [&] {
      std::array<nebula::PassbandEdit, 3> bands{};
      bands[1].shiftNm = ++edits % 2 ? 5.0 : -5.0;
      auto next = std::make_unique<nebula::NebulaRenderer>(renderer, renderer.model().filters, bands);
      if (!marcher.refilter(*next)) throw Error("nebula bench: a projection march did not stand a filter edit");
      edited = std::move(next);  // after the marcher let go of the last one
      marcher.finishOnGpu();
      glFinish();
    });
    auto cpuCell = [](double ms) { return std::isnan(ms) ? std::string("—") : fmt::format("{:.1f}", ms); };
    fmt::print("{:>5} {:>14} {:>14} {:>14.1f} {:>14.1f} {:>16.1f} {:>14.1f}x {:>14.1f}x {:>16.1f}\n", stars,
               cpuCell(reference), cpuCell(cpuProjection), gpuReference, gpuProjection, gpuLight,
               gpuReference / gpuProjection, gpuReference / gpuLight, filterEdit);
  }
}

}  // namespace prism::app

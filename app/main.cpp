// The prism command line: one subcommand per job, each in its own file. CLI11's headers cost ~15 s
// per file on 2 cores, so few files include them (this one, cli_settings.h, colour_command_line.cpp,
// nebula_command_line.cpp and parse_error_hint.cpp).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "app/benchmark_command.h"
#include "app/camera_option.h"
#include "app/cli_settings.h"
#include "app/cluster_command.h"
#include "app/colour_command_line.h"
#include "app/merge_command.h"
#include "app/nebula_command_line.h"
#include "app/option_error.h"
#include "app/option_lists.h"
#include "app/parse_error_hint.h"
#include "app/prt_commands.h"
#include "app/reference_commands.h"
#include "app/render_commands.h"
#include "app/settings_command.h"
#include "app/upsampling_commands.h"
#include "app/view_command.h"
#include "app/wavelength_commands.h"
#include "gpu/error.h"
#include "harness/colour_checker_chart.h"
#include "harness/compare_report.h"
#include "harness/gallery.h"
#include "harness/scene_bench.h"
#include "harness/sky_experiments.h"
#include "harness/validate.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "core/task_split.h"
#include "render/setting_keys.h"
#include "spectral/sampling.h"
#include "viewer/viewer.h"

namespace {

using prism::app::CliSettings;

// The options of `prism reference` that shape one render, also taken by `prism cluster script
// reference` to write the tasks' command lines.
void addReferenceOptions(CLI::App* command, prism::app::ReferenceOptions& ref, std::string& refRange, std::string& refEv,
                         prism::app::CliSettings& display) {
  command->add_option("scene", ref.scene, "scene file (JSON, see docs/scene-format.md)")->required();
  command->add_option("-o,--output", ref.output, "OUT.exr or OUT.png")->required();
  command->add_option("--variance", ref.variance, "also write the per-pixel variance of the mean (EXR)");
  command->add_option("--set", ref.sets, "override a scene value: json.path=value (repeatable)");
  command->add_option("--width", ref.width, "image width")->capture_default_str();
  command->add_option("--height", ref.height, "image height")->capture_default_str();
  command->add_option("--spp", ref.samplesPerPixel, "paths per pixel (4 wavelengths each)")->capture_default_str();
  command->add_option("--transport", ref.transport, "direct (what the rasteriser computes) or global")
      ->capture_default_str();
  command->add_option("--max-depth", ref.maxDepth, "with --transport global: interactions per path at most (16)");
  command->add_option("--filter", ref.filter, "box (antialiased) or centre (pixel centres, as a rasteriser)")
      ->capture_default_str();
  CLI::Option* observer = command->add_option("--observer", ref.observer, "cie1931, cie1964 or a camera")->capture_default_str();
  command->add_option("--camera", ref.camera, "a camera as the observer (raw camera RGB)")
      ->excludes(observer)
      ->check(prism::app::cameraName());
  command->add_option("--range", refRange, "MIN,MAX nm of the hero wavelengths (within 360–830)");
  command->add_option("--strategy", ref.strategy,
                           "lights (the scene's emission × the observer's response), importance (the response "
                           "alone), rotated, stratified or uniform")
      ->capture_default_str();
  command->add_option("--seed", ref.seed, "random seed (the image depends on it alone)")->capture_default_str();
  command->add_option("--threads", ref.threads, "worker threads (0: all)")->check(CLI::Range(0u, prism::kMaxThreads));
  command->add_option("--ev", refEv, "exposure EV100 for the PNG and the display white (default: the scene camera's)");
  display.addTo(command, prism::app::isReferenceDisplayKey);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace prism::app;
  using namespace prism::harness;
  CLI::App app{"Prism: real-time spectral rendering. Run `prism COMMAND --help` for a command."};
  app.require_subcommand(1);

  GalleryOptions gallery;
  auto* demoCmd = app.add_subcommand(
      "demo", "Prism's main job: every example scene in RGB and spectral mode side by side, and the "
              "ColorChecker chart, in a folder with an index.html");
  demoCmd->add_option("-o,--output", gallery.output, "folder to write")->capture_default_str();
  demoCmd->add_option("--scenes", gallery.scenes, "folder of scene files (default: the example scenes)");
  demoCmd->add_option("--width", gallery.width, "image width")->capture_default_str();
  demoCmd->add_option("--height", gallery.height, "image height")->capture_default_str();
  demoCmd->add_option("--wavelengths", gallery.wavelengths,
                      "wavelengths of the spectral images (fitted for each scene's lights; 4–64)")
      ->capture_default_str();

  DemoOptions demo;
  auto* chartCmd = app.add_subcommand("chart", "the ColorChecker under D65, A, F2, F11 as a PNG chart");
  chartCmd->add_option("-o,--output", demo.output, "PNG to write")->capture_default_str();
  chartCmd->add_option("--adaptation", demo.adaptation, "white balance to D65: bradford, cat02, von-kries, none")
      ->capture_default_str();
  chartCmd->add_flag("--json", demo.json, "print the patch values as JSON");

  prism::app::addColourCommands(app);

  auto* prtCmd = app.add_subcommand("prt", "spectral precomputed radiance transfer (SH-5 × SVD basis)");
  prtCmd->require_subcommand(1);
  PrtBakeOptions prtBake;
  auto* prtBakeCmd = prtCmd->add_subcommand("bake", "bake (or read from the cache) the SH-5 transfer of a scene's or model's vertices");
  prtBakeCmd->add_option("input", prtBake.input, "scene (.json) or glTF model (.gltf, .glb)")->required();
  prtBakeCmd->add_option("--samples", prtBake.samples, "directions per vertex (default: the scene's prt.samples, else 1024)");
  prtBakeCmd->add_flag_callback("--no-shadows", [&prtBake] { prtBake.shadows = false; },
                                "unshadowed transfer (so is a scene's whose prt.shadows is false)");
  prtBakeCmd->add_option("--cache", prtBake.cacheDir, "cache folder (default: Prism's cache)");
  prtBakeCmd->add_option("--part", prtBake.part, "I/N, I from 0 (a Slurm array task id): only task I of N's share of the vertices, as a part for `prism merge` (-o)");
  prtBakeCmd->add_option("-o,--output", prtBake.output, "the part's file (with --part)");
  prtBakeCmd->add_option("--threads", prtBake.threads, "worker threads (0: every core)")->capture_default_str()->check(CLI::Range(0u, prism::kMaxThreads));
  PrtReportOptions prtReport;
  auto* prtReportCmd = prtCmd->add_subcommand("report", "the ColorChecker object (or a scene): spectral PRT (m = 1..16) and RGB-PRT against 5 nm sampling");
  prtReportCmd->add_option("input", prtReport.input, "a scene (.json) or glTF model instead of the ColorChecker height field");
  prtReportCmd->add_option("--illuminant", prtReport.illuminant, "illuminant of a sky or uniform environment (default: F4)");
  prtReportCmd->add_option("--environment", prtReport.environment, "sky (overcast gradient; the default, unless a scene brings its own), uniform, or atmosphere (Prism's spectral sky and sun)");
  prtReportCmd->add_option("--sun-elevation", prtReport.sunElevationDeg, "the atmosphere's sun, degrees above the horizon (default: the scene's sky's, else 30)");
  prtReportCmd->add_option("--sun-azimuth", prtReport.sunAzimuthDeg, "the atmosphere's sun, degrees (0: towards -z, 90: +x; default: the scene's sky's, else 180)");
  prtReportCmd->add_option("--map,--exr", prtReport.exr, "an equirectangular map instead, row 0 at the zenith: linear-sRGB EXR or Radiance .hdr");
  std::string prtRotate;
  prtReportCmd->add_option("--rotate", prtRotate, "X,Y,Z,DEGREES: turn the environment (SH rotation, no re-projection)");
  prtReportCmd->add_option("--patch-vertices", prtReport.patchVertices,
                           "without an input: vertices along each side of a ColorChecker patch (default 16)");
  prtReportCmd->add_option("--samples", prtReport.samples, "directions per vertex (default: the scene's prt.samples, else 1024)");
  prtReportCmd->add_option("--plot", prtReport.plotFile, "SVG of the error against m to write");
  prtReportCmd->add_option("--colours", prtReport.coloursFile, "PLY of per-vertex display sRGB colours to write");
  prtReportCmd->add_option("--colours-m", prtReport.coloursM, "basis size of those colours (0: the 5 nm reference; default 8, or fewer when the scene's spectra give fewer)");
  prtReportCmd->add_flag("--json", prtReport.json, "JSON output");
  PrtMetamersOptions prtMetamers;
  auto* prtMetamersCmd = prtCmd->add_subcommand("metamers", "a reflectance and its metamer on one object, rendered by spectral PRT under several skies");
  prtMetamersCmd->add_option("--reflectance", prtMetamers.reflectance, "a ColorChecker patch name or a spectral CSV")->capture_default_str();
  prtMetamersCmd->add_option("--match", prtMetamers.match, "illuminant under which the two match")->capture_default_str();
  prtMetamersCmd->add_option("--target", prtMetamers.target, "illuminant under which they differ most")->capture_default_str();
  std::string prtMetamersUnder = fmt::format("{}", fmt::join(prtMetamers.under, ","));
  auto* prtMetamersUnderOpt = prtMetamersCmd->add_option("--under", prtMetamersUnder,
                                                         "illuminants of the skies to render under, comma-separated")
                                  ->capture_default_str();
  prtMetamersCmd->add_option("--patch-vertices", prtMetamers.patchVertices, "vertices along each side of a patch")->capture_default_str();
  prtMetamersCmd->add_option("--samples", prtMetamers.samples, "directions per vertex")->capture_default_str();
  prtMetamersCmd->add_flag("--json", prtMetamers.json, "JSON output");

  LutOptions lut;
  auto* lutCmd = app.add_subcommand("lut", "build a Jakob–Hanika upsampling table with Prism's optimiser");
  lutCmd->add_option("--gamut", lut.gamut, "srgb, display-p3, rec2020, acescg, aces2065-1")->capture_default_str();
  lutCmd->add_option("--res", lut.resolution, "nodes per axis (5–256)")->capture_default_str();
  lutCmd->add_option("-o,--output", lut.output, "table file to write")->required();
  lutCmd->add_option("--threads", lut.threads, "worker threads (0: all)")->check(CLI::Range(0u, prism::kMaxThreads));
  lutCmd->add_flag("--report", lut.report, "measure node and round-trip CIEDE2000 after building");
  lutCmd->add_flag("--json", lut.json, "JSON output");
  lutCmd->add_option("--part", lut.part, "I/N, I from 0 (a Slurm array task id): only task I of N's columns of the table, as a part for `prism merge`");

  UpsampleOptions up;
  std::string upRgb, upWavelengths;
  auto* upCmd = app.add_subcommand("upsample", "RGB → sigmoid coefficients and spectrum through the cached table");
  upCmd->add_option("--rgb", upRgb, "r,g,b, linear")->required();
  upCmd->add_option("--gamut", up.gamut, "colour space of --rgb (default srgb)");
  upCmd->add_option("--res", up.resolution,
                    fmt::format("table resolution (default {})", prism::kRendererTableResolution));
  upCmd->add_option("--wavelengths", upWavelengths, "MIN:MAX:STEP in nm (default 360:830:5)");
  upCmd->add_option("--intent", up.intent, "albedo (clamped to [0, 1]) or unbounded (scaled by 2·max)")->capture_default_str();
  upCmd->add_option("--path", up.path, "manual or filtered lookup (default manual)");
  upCmd->add_option("--method", up.method, "jakob-hanika, or box (the thesis's naive blue/green/red bands)")
      ->capture_default_str();
  upCmd->add_flag("--json", up.json, "JSON output");

  RenderOptions render;
  CliSettings renderSettings;
  auto* renderCmd = app.add_subcommand("render", "render a scene headlessly to a PNG (display) or an EXR (linear XYZ)");
  renderCmd->add_option("scene", render.scene, "scene file (JSON, see docs/scene-format.md)")->required();
  renderCmd->add_option("-o,--output", render.output, "OUT.png or OUT.exr")->required();
  renderCmd->add_option("--frames", render.frames, "frames accumulated (stochastic strategies converge)")
      ->capture_default_str();
  renderCmd->add_option("--set", render.sets, "override a scene value: json.path=value (repeatable)");
  renderSettings.addTo(renderCmd);

  auto* wavelengthsCmd = app.add_subcommand("wavelengths", "the optimised strategy's wavelengths for a scene's lights");
  wavelengthsCmd->require_subcommand(1);
  WavelengthsOptimiseOptions wavelengthsOptimise;
  CliSettings wavelengthsSettings;
  auto* wavelengthsOptimiseCmd = wavelengthsCmd->add_subcommand(
      "optimise", "fit (or read from the cache) n wavelengths and a 3×n matrix for a scene's lights, with a report");
  wavelengthsOptimiseCmd->add_option("scene", wavelengthsOptimise.scene, "scene file (JSON)")->required();
  wavelengthsOptimiseCmd->add_option("--set", wavelengthsOptimise.sets, "override a scene value: json.path=value (repeatable)");
  wavelengthsOptimiseCmd->add_flag("--json", wavelengthsOptimise.json, "JSON output");
  // The fit's own settings: the count, the range and the observer (the strategy is optimised).
  wavelengthsSettings.addTo(wavelengthsOptimiseCmd, [](std::string_view key) {
    return key == "wavelengths" || key == "range" || key == "observer";
  });

  CliSettings settingsSettings;
  bool settingKeys = false;
  auto* settingsCmd = app.add_subcommand(
      "settings", "print the frame settings these options give, a `KEY VALUE` line each: the keys of render, "
                  "view and bench options, of the viewer's `set` and of its settings files");
  settingsSettings.addTo(settingsCmd);
  settingsCmd->add_flag("--keys", settingKeys, "print the table of keys instead (Markdown)");

  ReferenceOptions ref;
  std::string refRange, refEv;
  CliSettings refDisplay;
  auto* referenceCmd = app.add_subcommand(
      "reference", "the ground truth: a CPU spectral path tracer (hero wavelengths, Embree) to an EXR "
                   "(linear XYZ in cd/m²) or a PNG");
  addReferenceOptions(referenceCmd, ref, refRange, refEv, refDisplay);
  referenceCmd->add_option("--tile", ref.tile,
                           "I/N, I from 0: only rows ⌊I·height/N⌋ to ⌊(I+1)·height/N⌋, as a part for `prism merge` (.exr)");
  referenceCmd->add_option("--samples", ref.samples,
                           "A:B: only path indices A to B (of --spp) of every pixel, as a part for `prism merge` (.exr)");

  MergeOptions merge;
  auto* mergeCmd = app.add_subcommand(
      "merge", "put the parts of a split reference render (--tile, --samples), table (lut --part) or PRT bake "
               "(prt bake --part) together; "
               "refuses gaps, overlaps and parts of another");
  mergeCmd->add_option("parts", merge.parts, "the part files (.exr, a table's or a bake's)")->required();
  mergeCmd->add_option("-o,--output", merge.output, "OUT.exr or OUT.png (a table, a bake: its file)")->required();
  mergeCmd->add_option("--variance", merge.variance, "also write the per-pixel variance of the mean (EXR)");
  CliSettings mergeDisplay;
  mergeDisplay.addTo(mergeCmd, isReferenceDisplayKey);

  ClusterOptions cluster;
  std::string clusterRange, clusterEv;
  CliSettings clusterDisplay;
  auto* clusterCmd = app.add_subcommand("cluster", "Prism's batch work on a Slurm cluster");
  clusterCmd->require_subcommand(1);
  auto* scriptCmd = clusterCmd->add_subcommand(
      "script", "print a bash script that submits the work as a Slurm array job of --tasks tasks and, after them, "
                "the job that puts their parts together (bash SCRIPT [INDICES] on a login node)");
  scriptCmd->require_subcommand(1);
  auto addClusterOptions = [&](CLI::App* command) {
    command->add_option("--tasks", cluster.tasks, "array tasks (Slurm --array=0-(N-1))")->required();
    command->add_option("--cpus", cluster.cpusPerTask, "CPUs per task (--cpus-per-task; prism's --threads)")
        ->capture_default_str();
    command->add_option("--time", cluster.time, "time limit of each task, HH:MM:SS")->capture_default_str();
    command->add_option("--sbatch", cluster.sbatchOptions,
                        "one more #SBATCH option for both jobs, e.g. --sbatch=--partition=gpu (repeatable)");
  };
  auto* scriptReferenceCmd = scriptCmd->add_subcommand(
      "reference", "`prism reference` split by --split rows (bit-identical) or samples, then `prism merge`");
  addReferenceOptions(scriptReferenceCmd, cluster.reference, clusterRange, clusterEv, clusterDisplay);
  addClusterOptions(scriptReferenceCmd);
  scriptReferenceCmd->add_option("--split", cluster.split, "rows (--tile I/N) or samples (--samples A:B)")
      ->capture_default_str();
  scriptReferenceCmd->add_option("--parts", cluster.parts, "folder of the parts and job logs (default: OUT.parts)");
  auto* scriptValidateCmd = scriptCmd->add_subcommand(
      "validate", "`prism validate --task I/N` (at most one task per experiment), then --collect");
  scriptValidateCmd->add_option("-o,--output", cluster.validate.output, "folder to write")->capture_default_str();
  scriptValidateCmd->add_option("--scenes", cluster.validate.scenes, "folder of the scene files (default: the example scenes)");
  scriptValidateCmd->add_flag("--quick", cluster.validate.quick, "240x135 and fewer paths per pixel");
  std::string clusterOnly;
  auto* clusterOnlyOpt = scriptValidateCmd->add_option("--only", clusterOnly,
                                                       "only these experiments, comma-separated (names as in results.json)");
  addClusterOptions(scriptValidateCmd);
  auto* scriptPrtCmd = scriptCmd->add_subcommand(
      "prt", "`prism prt bake --part I/N` (a share of the vertices each), then `prism merge` into the cache's transfer file");
  scriptPrtCmd->add_option("input", cluster.prt.input, "scene (.json) or glTF model (.gltf, .glb)")->required();
  scriptPrtCmd->add_option("--samples", cluster.prt.samples, "directions per vertex (default: the scene's prt.samples, else 1024)");
  scriptPrtCmd->add_flag_callback("--no-shadows", [&cluster] { cluster.prt.shadows = false; },
                                  "unshadowed transfer (so is a scene's whose prt.shadows is false)");
  scriptPrtCmd->add_option("--cache", cluster.prt.cacheDir, "cache folder the merged bake goes to (default: Prism's cache)");
  addClusterOptions(scriptPrtCmd);
  auto* scriptLutCmd = scriptCmd->add_subcommand(
      "lut", "`prism lut --part I/N` (a share of the table's 3·res² columns each), then `prism merge`");
  scriptLutCmd->add_option("--gamut", cluster.lut.gamut, "srgb, display-p3, rec2020, acescg, aces2065-1")->capture_default_str();
  scriptLutCmd->add_option("--res", cluster.lut.resolution, "nodes per axis (5–256)")->capture_default_str();
  scriptLutCmd->add_option("-o,--output", cluster.lut.output, "table file to write")->required();
  addClusterOptions(scriptLutCmd);

  CompareOptions cmp;
  double cmpWhite = 0.0;
  auto* compareCmd = app.add_subcommand("compare", "CIEDE2000 and MAE between a reference and a test image (EXR or PNG)");
  compareCmd->add_option("reference", cmp.reference, "reference image (.exr XYZ or linear sRGB, or 8-bit .png)")->required();
  compareCmd->add_option("test", cmp.test, "test image, the same size")->required();
  // An empty name is not "no heat map" (it was, exit 0, and --scale-max then said none was asked for).
  const CLI::Validator nonEmptyFileName(
      [](std::string& name) { return name.empty() ? std::string("an output's file name is empty") : std::string(); }, "");
  compareCmd->add_option("--heatmap", cmp.heatmap, "write a ΔE00 heat map (PNG)")->check(nonEmptyFileName);
  compareCmd->add_option("--histogram", cmp.histogram, "write a ΔE00 histogram (PNG)")->check(nonEmptyFileName);
  auto* whiteOpt = compareCmd->add_option("--white", cmpWhite,
                                          "luminance of white for linear images (default: the file's display white, else 1)");
  compareCmd->add_option("--threshold", cmp.threshold, "ΔE00 above which a pixel fails")->capture_default_str();
  compareCmd->add_option("--scale-max", cmp.scaleMax, "ΔE00 at the top of the heat map and histogram (default 10)");
  compareCmd->add_flag("--json", cmp.json, "JSON output");

  ValidateOptions val;
  auto* validateCmd = app.add_subcommand(
      "validate", "the thesis's experiments: the rasteriser's modes against the reference path tracer, "
                  "with an HTML report; fails when a bound is broken");
  validateCmd->add_option("-o,--output", val.output, "folder to write")->capture_default_str();
  validateCmd->add_option("--scenes", val.scenes, "folder of the scene files (default: the example scenes)");
  validateCmd->add_flag("--quick", val.quick, "240x135 and fewer paths per pixel (seconds on 2 cores), for CI");
  validateCmd->add_flag("--json", val.json, "JSON output");
  validateCmd->add_option("--task", val.task,
                          "I/N, I from 0: only task I of N's share of the experiments, as a part in OUT/parts (a Slurm array task)");
  auto* collectFlag = validateCmd->add_flag("--collect", val.collect, "the report from the parts in OUT/parts (after every --task)")
                          ->excludes("--task");
  validateCmd->add_option("--tasks", val.tasks, "with --collect: only the parts of a split into N tasks (task-*-of-N.json)")
      ->needs(collectFlag)
      ->check(CLI::Range(1, prism::kMaxTasks));
  std::string validateOnly;
  auto* validateOnlyOpt = validateCmd->add_option(
      "--only", validateOnly, "only these experiments (names as in results.json, e.g. spheres_d65,reef_5m)");
  validateCmd->add_option("--threads", val.threads, "CPU threads for the path tracer, bakes and references (0: all)")
      ->check(CLI::Range(0u, prism::kMaxThreads));

  ViewOptions view;
  CliSettings viewSettings;
  auto* viewCmd = app.add_subcommand("view", "the interactive viewer: a window with every spectral setting live");
  viewCmd->add_option("scene", view.scene, "scene file (JSON, see docs/scene-format.md)")->required();
  viewCmd->add_option("--script", view.script, "run these viewer commands (README), then close");
  viewCmd->add_option("--set", view.sets, "override a scene value: json.path=value (repeatable)");
  viewSettings.addTo(viewCmd);
  for (const char* side : {"width", "height"})
    viewSettings.describe(side, fmt::format("window {}: a whole number within {}–{}", side, prism::viewer::kMinWindowSide,
                                            prism::viewer::kMaxWindowSide));

  SceneBenchOptions sceneBench;
  CliSettings benchSettings;
  std::string benchWavelengths;
  AtmosphereCommandOptions atm;
  auto* atmosphereCmd = app.add_subcommand("atmosphere", "the spectral sky: wavelength strategies against the reference");
  atmosphereCmd->require_subcommand(1);
  auto* atmEvaluate = atmosphereCmd->add_subcommand(
      "evaluate", "mean and max CIEDE2000 of RGB-3, uniform 4, optimised 4 (8 and 12 parameters) and uniform 16 "
                  "against the reference sky, per sun elevation (exit 1 when the optimised set misses ΔE00 1.0)");
  auto* atmOptimise = atmosphereCmd->add_subcommand(
      "optimise", "fit the four wavelengths and weights (and the 3x4 matrix), with and without aerosols");
  for (CLI::App* c : {atmEvaluate, atmOptimise}) {
    c->add_option("--reference-step", atm.referenceStepNm, "nm between the reference's wavelengths (0.5..50; default 1, --quick 10)");
    c->add_option("--zeniths", atm.zeniths, "view zenith bins over the upper hemisphere (1..512; default 16, --quick 8)");
    c->add_option("--azimuths", atm.azimuths, "view azimuth bins over 0..180° from the sun (1..1024; default 32, --quick 16)");
    c->add_flag("--quick", atm.quick, "10 nm reference, 8 x 16 directions (seconds) where those options are not given");
  }
  atmEvaluate->add_flag_callback("--no-aerosols", [&atm] { atm.aerosols = false; }, "Rayleigh + ozone only (and its optimised set)");
  atmEvaluate->add_option("--wavelengths", atm.wavelengths, "an optimised wavelength file (default: data/atmosphere_wavelengths.json)");
  atmEvaluate->add_flag("--json", atm.json, "JSON output");
  atmOptimise->add_option("-o,--output", atm.output, "where to write (the shipped fit is data/atmosphere_wavelengths.json: name it to replace it)")->required();

  prism::app::addNebulaCommands(app);

  auto* bench = app.add_subcommand(
      "bench", "GPU frame times of a scene (prism bench SCENE.json), or, without a scene, Prism's "
               "micro-benchmarks (Google Benchmark flags pass through)");
  bench->allow_extras();
  bench->add_option("scene", sceneBench.scene, "scene file: time its passes in RGB and spectral modes");
  // Its own --wavelengths; the mode is the bench's per configuration (RGB and Jakob–Hanika).
  benchSettings.addTo(bench, [](std::string_view key) { return key != "wavelengths" && key != "mode"; });
  auto* benchWavelengthsOpt =
      bench->add_option("--wavelengths", benchWavelengths,
                        "wavelength counts, comma-separated (default 4,8,16,32,64,128,256; up to 64 with the optimised "
                        "strategy)");
  bench->add_option("--frames", sceneBench.frames, "timed frames per configuration, spread over the rounds")
      ->capture_default_str();
  bench->add_option("--rounds", sceneBench.rounds, "rounds over every configuration in turn (load drift cancels "
                    "in per-round ratios; default 5, or --frames when fewer)");
  bench->add_option("--warmup", sceneBench.warmup, "untimed frames before each configuration in every round")
      ->capture_default_str();
  bench->add_option("--plot", sceneBench.plot, "SVG plot of frame time against the wavelength count");
  bench->add_flag("--json", sceneBench.json, "JSON output");

  // After every option is added; the frame settings' keys are parsed by their table.
  const std::array<const CliSettings*, 5> settingsOptions{&renderSettings, &wavelengthsSettings, &settingsSettings,
                                                          &viewSettings, &benchSettings};
  prism::app::requireDecimalNumbers(app, [&](const CLI::Option* option) {
    return std::any_of(settingsOptions.begin(), settingsOptions.end(), [&](const CliSettings* s) { return s->owns(option); });
  });
  try {
    app.parse(argc, argv);
    if (*demoCmd) runGallery(gallery);
    if (*chartCmd) runDemo(demo);
    if (*prtBakeCmd) runPrtBake(prtBake);
    if (*prtReportCmd) {
      if (!prtRotate.empty()) prtReport.rotate = prism::app::parseNumbers(prtRotate, "--rotate");
      runPrtReport(prtReport);
    }
    if (*prtMetamersCmd) {
      if (prtMetamersUnderOpt->count() > 0) prtMetamers.under = prism::app::parseNames(prtMetamersUnder, "--under");
      runPrtMetamers(prtMetamers);
    }
    if (*lutCmd) runLut(lut);
    if (*upCmd) {
      up.rgb = prism::app::parseNumbers(upRgb, "--rgb");
      if (!upWavelengths.empty()) up.wavelengths = prism::app::parseNumbers(upWavelengths, "--wavelengths", ':');
      runUpsample(up);
    }
    if (*settingsCmd) printSettings(settingsSettings.given(), settingKeys);
    if (*wavelengthsOptimiseCmd) {
      wavelengthsOptimise.settings = wavelengthsSettings.given();
      runWavelengthsOptimise(wavelengthsOptimise);
    }
    if (*renderCmd) {
      render.settings = renderSettings.given();
      runRender(render);
    }
    if (*referenceCmd) {
      if (!refRange.empty()) ref.range = prism::app::parseNumbers(refRange, "--range");
      if (!refEv.empty()) ref.ev100 = static_cast<float>(prism::app::parseNumber(refEv, "--ev"));
      ref.display = refDisplay.given();
      runReference(ref);
    }
    if (*mergeCmd) {
      merge.display = mergeDisplay.given();
      runMerge(merge);
    }
    if (*scriptReferenceCmd) {
      if (!clusterRange.empty()) cluster.reference.range = prism::app::parseNumbers(clusterRange, "--range");
      if (!clusterEv.empty()) cluster.reference.ev100 = static_cast<float>(prism::app::parseNumber(clusterEv, "--ev"));
      cluster.reference.display = clusterDisplay.given();
      printReferenceClusterScript(cluster);
    }
    if (*scriptValidateCmd) {
      if (clusterOnlyOpt->count() > 0) cluster.validate.only = prism::app::parseNames(clusterOnly, "--only");
      printValidateClusterScript(cluster);
    }
    if (*scriptLutCmd) printLutClusterScript(cluster);
    if (*scriptPrtCmd) printPrtClusterScript(cluster);
    if (*compareCmd) {
      if (whiteOpt->count() > 0) cmp.white = cmpWhite;
      runCompare(cmp);
    }
    if (*atmEvaluate) return runAtmosphereEvaluate(atm);
    if (*atmOptimise) runAtmosphereOptimise(atm);
    if (*validateCmd) {
      if (validateOnlyOpt->count() > 0) val.only = prism::app::parseNames(validateOnly, "--only");
      return runValidate(val);
    }
    if (*viewCmd) {
      view.settings = viewSettings.given();
      return runView(view);
    }
    if (*bench && !sceneBench.scene.empty()) {
      if (!bench->remaining().empty()) {  // a malformed command line: exit 2
        if (bench->remaining().front().starts_with("--mode"))
          throw CLI::ValidationError("--mode", "the bench sets the mode per configuration (rgb and jakob-hanika)");
        throw CLI::ExtrasError(bench->remaining());
      }
      sceneBench.settings = frameSettings(benchSettings.given());
      sceneBench.settings.mode = prism::render::RenderMode::Rgb;  // the bench sets the mode per configuration
      if (benchWavelengthsOpt->count() > 0) {  // given empty, it is refused, not the default
        sceneBench.wavelengths.clear();
        for (double n : prism::app::parseNumbers(benchWavelengths, "--wavelengths")) {
          if (n != std::trunc(n) || std::abs(n) > 1e6)
            throw prism::Error(fmt::format("--wavelengths: {:g} is not a whole number of wavelengths", n));
          if (std::ranges::count(sceneBench.wavelengths, static_cast<int>(n)) > 0)
            throw prism::Error(fmt::format("--wavelengths: {:g} is given twice", n));
          prism::app::fromOption("--wavelengths", [n] { prism::validateWavelengthCount(static_cast<int>(n)); });
          sceneBench.wavelengths.push_back(static_cast<int>(n));
        }
      } else if (sceneBench.settings.sampling.strategy == prism::SamplingStrategy::Optimised) {
        // A fitted set has at most 64 wavelengths: the default sweep stops there.
        std::erase_if(sceneBench.wavelengths, [](int n) { return n > prism::kMaxFittedWavelengths; });
      }
      runSceneBench(sceneBench);
    } else if (*bench) {
      // Without a scene the micro-benchmarks run, which take Google Benchmark's flags alone.
      for (const CLI::Option* option : bench->get_options())
        if (option->count() > 0)
          throw CLI::ValidationError(option->get_name(), "only with a scene (prism bench SCENE.json); without one, "
                                                         "bench runs the micro-benchmarks, which take Google "
                                                         "Benchmark's flags");
      return prism::app::runBenchmarks(bench->remaining());
    }
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 reports a missing subcommand before a word it did not expect: name that word.
    std::vector<std::string> rest = app.remaining(true);
    if (dynamic_cast<const CLI::RequiredError*>(&e) && !rest.empty())
      fmt::print(stderr, "prism: error: unknown command or argument '{}' (see prism --help)\n", rest.front());
    else if (dynamic_cast<const CLI::RequiredError*>(&e) && std::string_view(e.what()) == "A subcommand is required")
      fmt::print(stderr, "prism: error: {}{}\n", e.what(), prism::app::subcommandHint(app));
    else if (dynamic_cast<const CLI::ExtrasError*>(&e))
      fmt::print(stderr, "prism: error: {}\n", prism::app::unexpectedArgumentsMessage(app, argc, argv, rest));
    else if (dynamic_cast<const CLI::ConversionError*>(&e))
      fmt::print(stderr, "prism: error: {}{}\n", e.what(), prism::app::conversionHint(app, e.what()));
    else
      fmt::print(stderr, "prism: error: {}\n", e.what());
    return 2;
  } catch (const prism::Error& e) {
    fmt::print(stderr, "prism: error: {}\n", e.what());
    return 1;
  } catch (const prism::gpu::GpuError& e) {
    fmt::print(stderr, "prism: error: {}\n", e.what());
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // The environment, not a bug: an output folder that cannot be made, a folder where a file
    // belongs, a path without permission.
    fmt::print(stderr, "prism: error: {}: {}\n", prism::excerpt(e.path1().string()), e.code().message());
    return 1;
  } catch (const std::bad_alloc&) {
    // The environment, not a bug: an image, grid or star count beyond this machine's memory.
    fmt::print(stderr, "prism: error: out of memory (a smaller image, grid or count may fit)\n");
    return 1;
  } catch (const std::exception& e) {
    // nlohmann::json (type_error 316) will not write text that is not UTF-8: a file's name in --json.
    const bool name = std::string_view(e.what()).starts_with("[json.exception.type_error.316]");
    fmt::print(stderr, "prism: {}: {}\n", name ? "error: a name in the output is not UTF-8" : "internal error", e.what());
    return name ? 1 : 70;
  }
  return 0;
}

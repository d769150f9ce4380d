#include "harness/scene_bench.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "gpu/headless_context.h"
#include "gpu/timer_query.h"
#include "harness/bench_plot.h"
#include "harness/bench_statistics.h"
#include "harness/progress_bar.h"
#include "harness/optimised_wavelengths.h"
#include "harness/technique_precompute.h"
#include "harness/upsampling_table.h"
#include "render/frame_data.h"
#include "render/renderer.h"
#include "render/setting_keys.h"
#include "scene/scene_loader.h"
#include "spectral/sampling.h"
#include "techniques/technique_pass.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"

namespace prism::harness {
namespace {

constexpr int kFramesInFlight = 3;  // the timer's ring
// A moving camera's pace: a brisk orbit, 60° a second at 60 frames a second.
constexpr float kOrbitDegPerFrame = 1.0f;

using PassTimes = std::map<std::string, double>;  // ms per pass and for the whole "frame"

// One configuration of the run: what renders it, with which settings, and what each round gave.
struct Config {
  std::string label;  // "rgb" or the wavelength count, …
  render::Renderer* renderer = nullptr;
  render::FrameSettings settings;
  int warmup = 0, frames = 0;  // per round
  int wavelengths = 0;         // spectral configurations of the fit; 0 otherwise
  bool still = false;          // frames accumulate as under a still camera; else each restarts
  bool wait = false;           // each frame's times waited for (measure): frames of seconds
  bool orbit = false;          // every frame restarts with the camera turned kOrbitDegPerFrame about its target
  int orbitFrames = 0;         // frames orbited so far: the orbit goes on from round to round
  long shadowMapsDrawn = 0, framesAfterWarmup = 0;  // summed over the rounds' frames after their warm-up
  double shadowMapsPerFrame() const {
    return framesAfterWarmup > 0 ? static_cast<double>(shadowMapsDrawn) / static_cast<double>(framesAfterWarmup) : 0.0;
  }
  // Frames rendered a round: the timed ones, the warm-up and, unless waited for, the ring's.
  int renderedPerRound() const { return warmup + frames + (wait ? 0 : kFramesInFlight); }
  std::vector<PassTimes> rounds;  // per round, the median of its frames
  std::size_t gpuMemoryBytes = 0;  // held by the renderer after the first round

  std::vector<double> frameMsPerRound() const {
    std::vector<double> ms;
    for (const PassTimes& r : rounds) ms.push_back(r.at("frame"));
    return ms;
  }
  // Per pass, the median over the rounds.
  PassTimes medianMs() const {
    std::map<std::string, std::vector<double>> perPass;
    for (const PassTimes& r : rounds)
      for (const auto& [pass, ms] : r) perPass[pass].push_back(ms);
    PassTimes out;
    for (auto& [pass, values] : perPass) out[pass] = median(values);
    return out;
  }
  double frameMs() const { return median(frameMsPerRound()); }
  double passMs(const char* pass) const {
    PassTimes m = medianMs();
    auto it = m.find(pass);
    return it == m.end() ? 0.0 : it->second;
  }
};

RatioSpread ratio(const Config& test, const Config& baseline) {
  return perRoundRatios(test.frameMsPerRound(), baseline.frameMsPerRound());
}

// `key`: the median of the per-round ratios; `key`_ci_low and _ci_high: its 95 % confidence
// interval (null under 6 rounds); `key`_min and _max: the extreme rounds.
void putRatio(nlohmann::json& j, const std::string& key, const RatioSpread& s) {
  j[key] = s.median;
  j[key + "_ci_low"] = s.confidence.low;
  j[key + "_ci_high"] = s.confidence.high;
  j[key + "_min"] = s.min;
  j[key + "_max"] = s.max;
}

double mebibytes(std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

// The camera turned about the vertical through its target.
Camera orbited(const Camera& camera, float degrees) {
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f));
  Camera c = camera;
  c.position = camera.target + glm::vec3(turn * glm::vec4(camera.position - camera.target, 0.0f));
  c.up = glm::vec3(turn * glm::vec4(camera.up, 0.0f));
  return c;
}

// One round of `c` on its renderer: every frame restarts as if camera and lights had moved (G-buffer
// and every shadow map drawn), or with `still` the frames after the first accumulate as a still
// camera's do, or with `orbit` the camera moves (the shadow maps whose view it moves drawn) and is
// put back after the round. With `wait` each timed frame's times are waited for (GpuTimer::resolve) rather
// than read kFramesInFlight frames later: for frames of seconds (a technique's reference), where
// the frames rendered only to push the last timed ones out of the ring cost more than the wait
// (the sky's reference: three more frames of 15 s a round at 64×36 on 2 idle cores, with the
// progress bar at 100 %). The bar counts every frame rendered.
PassTimes measure(Config& c, gpu::GpuTimer& timer, ProgressBar& bar, std::size_t& done, std::size_t total) {
  render::Renderer& renderer = *c.renderer;
  const Camera start = renderer.camera();
  const int warmup = c.warmup;
  const bool still = c.still, wait = c.wait;
  std::map<std::string, std::vector<double>> samples;
  auto collect = [&](const gpu::GpuTimings& timings) {
    std::map<std::string, double> frame;  // a technique's passes before and after lighting share its name
    for (const auto& [name, ms] : timings) frame[name] += ms;
    for (const auto& [name, ms] : frame) samples[name].push_back(ms);
  };
  bool open = false;
  renderer.setPassHook([&](std::string_view pass) {
    if (open) timer.endScope();
    open = !pass.empty();
    if (open) timer.beginScope(pass);
  });
  // A frame's times arrive kFramesInFlight frames later: render that many more frames than are
  // timed, so that exactly c.frames frames after the warm-up are collected, none waited for.
  for (int f = 0; f < c.renderedPerRound(); ++f) {
    timer.beginFrame();
    if (!wait && f >= warmup + kFramesInFlight) collect(timer.latest());
    if (c.orbit)
      renderer.setCamera(orbited(start, kOrbitDegPerFrame * static_cast<float>(++c.orbitFrames)));
    else if (!still || f == 0)
      renderer.resetAccumulation();
    renderer.renderFrame();
    timer.endFrame();
    if (f >= warmup) {
      c.shadowMapsDrawn += renderer.shadowLayersDrawn();
      ++c.framesAfterWarmup;
    }
    if (wait && f >= warmup) collect(timer.resolve());
    bar.update(++done, total);
  }
  renderer.setPassHook({});
  if (c.orbit) renderer.setCamera(start);
  PassTimes result;
  for (auto& [name, values] : samples) result[name] = median(values);
  return result;
}

}  // namespace

void runSceneBench(const SceneBenchOptions& options) {
  if (options.wavelengths.empty()) throw Error("--wavelengths: give at least one count");
  // A million frames is hours of a GPU's time; more overflowed the frame counters' int sums.
  if (options.frames < 1 || options.warmup < 0 || options.rounds.value_or(1) < 1 || options.frames > kMaxBenchFrames ||
      options.warmup > kMaxBenchFrames)
    throw Error(fmt::format("--frames and --rounds must be within 1–{0}, --warmup within 0–{0}", kMaxBenchFrames));
  if (options.rounds > options.frames)  // it ran fewer rounds than asked, saying "1 rounds"
    throw Error(fmt::format("--rounds {}: more rounds than --frames {} (a round times at least one frame of each "
                            "configuration)", *options.rounds, options.frames));
  if (!options.plot.empty()) {
    requireExtension(options.plot, ".svg", "--plot", "plot");
    requireWritable(options.plot);
  }
  const render::FrameSettings& settings = options.settings;
  std::vector<int> counts = options.wavelengths;
  counts.push_back(16);  // the bench's own configurations (G-buffer, still camera, strategies)
  for (int n : counts) {  // as the spectral configurations take them (the RGB one takes CIE 1931, below)
    render::FrameSettings check = settings;
    check.mode = render::RenderMode::JakobHanika;
    check.sampling.count = n;
    render::validate(check);
  }
  const int rounds = options.rounds.value_or(std::min(kDefaultBenchRounds, options.frames));
  const int frames = (options.frames + rounds - 1) / rounds;  // per round
  Scene scene = loadScene(options.scene);
  render::requireLightCount(scene);  // the renderer's own checks, before the work ahead of them
  render::requireTechniquesShow(scene, settings);
  gpu::HeadlessContext context;
  requireTechniquesFit(scene);  // this GPU's limits, before the work ahead of it too
  const RgbToSpectrumTable& table = upsamplingTable(scene);
  precomputeTechniques(scene);
  std::string device = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  render::FrameSettings rgbSettings = settings;
  rgbSettings.observer = "cie1931";  // RGB mode's own: its colour spaces are defined on it
  render::Renderer renderer(scene, table, rgbSettings);
  gpu::GpuTimer timer({kFramesInFlight});

  std::vector<Config> configs;
  auto add = [&](std::string label, render::Renderer& r, const render::FrameSettings& s) -> std::size_t {
    Config& c = configs.emplace_back();
    c.label = std::move(label);
    c.renderer = &r;
    c.settings = s;
    c.warmup = options.warmup;
    c.frames = frames;
    return configs.size() - 1;
  };
  auto spectralSettings = [&](int n) {
    render::FrameSettings s = settings;
    s.mode = render::RenderMode::JakobHanika;
    s.sampling.count = n;
    return s;
  };
  const std::size_t rgb = add("rgb", renderer, rgbSettings);
  std::vector<std::size_t> spectral;
  for (int n : options.wavelengths) {
    spectral.push_back(add(std::to_string(n), renderer, spectralSettings(n)));
    configs.back().wavelengths = n;
  }

  // What the G-buffer keeps of a base colour (issue #4: which is faster?): RGB albedo, upsampled
  // once per pixel in the lighting pass, against Jakob–Hanika coefficients looked up per G-buffer
  // fragment into one more RGBA32F target; 16 wavelengths.
  render::FrameSettings rgbAlbedo = spectralSettings(16);
  rgbAlbedo.gbufferAlbedo = render::GBufferAlbedo::Rgb;
  render::FrameSettings coefficientAlbedo = rgbAlbedo;
  coefficientAlbedo.gbufferAlbedo = render::GBufferAlbedo::Coefficients;
  const std::size_t coefficients16 = add("16 coefficients", renderer, coefficientAlbedo);
  const std::size_t rgbAlbedo16 = add("16 rgb albedo", renderer, rgbAlbedo);
  // A still camera's frame at 16 wavelengths, which draws from the lighting pass on (the shadow
  // maps and G-buffer hold while frames accumulate), against a restart's that draws them all.
  const std::size_t still16 = add("16 still", renderer, spectralSettings(16));
  configs[still16].still = true;
  configs[still16].warmup = std::max(options.warmup, 1);
  const std::size_t moving16 =
      settings.gbufferAlbedo == render::GBufferAlbedo::Coefficients ? coefficients16 : rgbAlbedo16;
  // A camera orbiting under still lights, against the same frame with every shadow map drawn
  // again (moving16): what keeping the maps whose view did not move saves.
  const render::FrameSettings movingSettings = configs[moving16].settings;  // add() grows configs
  const std::size_t orbiting16 = add("16 orbiting", renderer, movingSettings);
  configs[orbiting16].orbit = true;

  // What each wavelength strategy costs a frame at 16 wavelengths (issue 16): the GPU draws 16
  // whatever the strategy; the CPU draws the set and builds its matrices per frame (the pdf or the
  // fitted set is built when the settings change, outside the timed frames). Against the rotated
  // grid, the strategy the others are measured by. A range the optimised set cannot be fitted over
  // leaves it out, saying why: the rest of the run is the user's.
  std::vector<std::pair<SamplingStrategy, std::size_t>> strategies16;
  for (SamplingStrategy strategy : {SamplingStrategy::Rotated, SamplingStrategy::Lights, SamplingStrategy::Optimised}) {
    render::FrameSettings s = spectralSettings(16);
    s.sampling.strategy = strategy;
    if (strategy == SamplingStrategy::Optimised && !holdsWholeNanometres(s.sampling.minNm, s.sampling.maxNm, 16)) {
      fmt::print(stderr, "prism: bench: the optimised strategy at 16 wavelengths is left out: it fits a whole nm per "
                         "wavelength, and --range {:g},{:g} holds fewer\n", s.sampling.minNm, s.sampling.maxNm);
      continue;
    }
    fitOptimisedWavelengths(scene, s, table);
    strategies16.emplace_back(strategy, add(fmt::format("16 {}", samplingStrategyName(strategy)), renderer, s));
  }

  // What each technique of the scene measures of its own cost (TechniqueSection::bench): its
  // configurations, on this renderer or on one whose scene lacks the technique.
  struct TechniqueRun {
    std::string key;
    std::vector<TechniqueBenchRatio> ratios;
    std::map<std::string, std::size_t> configs;  // label → index into configs, "rgb" included
  };
  std::vector<TechniqueRun> techniqueRuns;
  std::vector<std::unique_ptr<render::Renderer>> renderersWithout;
  std::deque<Scene> scenesWithout;  // the renderers' scenes (without a technique, or with another
                                    // version of its section): references stay valid as it grows
  const auto lamps = static_cast<std::size_t>(
      std::ranges::count_if(scene.lights, [](const Light& l) { return l.type != LightType::Directional; }));
  for (const auto& section : scene.techniques.all()) {
    TechniqueBench bench = section->bench(lamps);
    if (bench.configs.empty()) continue;
    TechniqueRun& run = techniqueRuns.emplace_back();
    run.key = section->key();
    run.ratios = bench.ratios;
    run.configs["rgb"] = rgb;
    render::Renderer* without = nullptr;
    for (const TechniqueBenchConfig& tc : bench.configs) {
      if (tc.withoutTechnique && !without) {
        Scene& s = scenesWithout.emplace_back(scene);
        s.techniques.remove(section->key());
        without = renderersWithout.emplace_back(std::make_unique<render::Renderer>(s, table, rgbSettings)).get();
      }
      render::Renderer* on = tc.withoutTechnique ? without : &renderer;
      if (tc.section) {  // the scene with another version of the technique's section
        Scene& other = scenesWithout.emplace_back(scene);
        other.techniques.add(tc.section->clone());
        on = renderersWithout.emplace_back(std::make_unique<render::Renderer>(other, table, rgbSettings)).get();
      }
      render::FrameSettings s = settings;
      for (const auto& [key, value] : tc.settings) PRISM_CHECK(render::applyFrameSetting(s, key, value));
      // RGB and optimised4 are defined on CIE 1931 (render::validate refuses them another
      // observer): they take it, as the run's RGB frames do. An observer's curves change the
      // frame's weights, not its cost.
      if (s.mode == render::RenderMode::Rgb || s.mode == render::RenderMode::Optimised4) s.observer = "cie1931";
      render::validate(s);
      const std::size_t i = add(tc.label, *on, s);
      if (tc.framesPerRound > 0) {
        configs[i].warmup = std::min(options.warmup, 1);
        configs[i].frames = tc.framesPerRound;
        configs[i].wait = true;
      }
      run.configs[tc.label] = i;
    }
    for (const TechniqueBenchRatio& r : run.ratios)
      PRISM_CHECK(run.configs.count(r.numerator) == 1 && run.configs.count(r.denominator) == 1);
  }

  std::size_t done = 0, total = 0;
  for (const Config& c : configs) total += static_cast<std::size_t>(rounds) * static_cast<std::size_t>(c.renderedPerRound());
  ProgressBar bar("benchmark " + options.scene.filename().string());
  for (int r = 0; r < rounds; ++r) {
    for (Config& c : configs) {
      c.renderer->setSettings(c.settings);
      c.rounds.push_back(measure(c, timer, bar, done, total));
      if (r == 0) c.gpuMemoryBytes = c.renderer->gpuMemoryBytes();
    }
  }

  std::vector<double> ns, ts;
  std::vector<BenchPoint> points;
  const Config* largest = &configs[spectral.front()];
  for (std::size_t i : spectral) {
    const Config& c = configs[i];
    std::vector<double> perRound = c.frameMsPerRound();
    ns.push_back(c.wavelengths);
    ts.push_back(c.frameMs());
    points.push_back({c.wavelengths, c.frameMs(), *std::min_element(perRound.begin(), perRound.end()),
                      *std::max_element(perRound.begin(), perRound.end())});
    if (c.wavelengths > largest->wavelengths) largest = &c;
  }
  const LinearFit fit = linearFit(ns, ts);
  const double rgbFrame = configs[rgb].frameMs();

  if (!options.plot.empty()) {
    writeFileAtomically(options.plot,
                        benchPlotSvg(points, rgbFrame, fit,
                                     fmt::format("{} at {}x{} on {}", options.scene.filename().string(),
                                                 settings.width, settings.height, device)));
  }
  if (options.json) {
    nlohmann::json j;
    j["scene"] = options.scene.string();
    j["device"] = device;
    j["width"] = settings.width;
    j["height"] = settings.height;
    j["frames"] = rounds * frames;
    j["rounds"] = rounds;
    j["frames_per_round"] = frames;
    j["rgb"] = configs[rgb].medianMs();
    for (std::size_t i : spectral) {
      const Config& c = configs[i];
      nlohmann::json e;
      e["wavelengths"] = c.wavelengths;
      e["median_ms"] = c.medianMs();
      putRatio(e, "ratio_to_rgb", ratio(c, configs[rgb]));
      e["gpu_memory_mb"] = mebibytes(c.gpuMemoryBytes);
      j["spectral"].push_back(e);
    }
    // A line through one wavelength count is no measurement: null then.
    if (spectral.size() > 1)
      j["fit"] = {{"slope_ms_per_wavelength", fit.slope}, {"intercept_ms", fit.intercept},
                  {"slope_fraction_of_rgb_frame", fit.slope / rgbFrame}};
    else
      j["fit"] = nullptr;
    j["gpu_memory_mb"] = {{"rgb", mebibytes(configs[rgb].gpuMemoryBytes)},
                          {"largest_wavelength_count", largest->wavelengths},
                          {"spectral_largest", mebibytes(largest->gpuMemoryBytes)},
                          {"coefficients_16", mebibytes(configs[coefficients16].gpuMemoryBytes)}};
    nlohmann::json& g = j["gbuffer_albedo_16"];
    g = {{"rgb_frame_ms", configs[rgbAlbedo16].frameMs()},
         {"coefficients_frame_ms", configs[coefficients16].frameMs()},
         {"rgb_median_ms", configs[rgbAlbedo16].medianMs()},
         {"coefficients_median_ms", configs[coefficients16].medianMs()}};
    putRatio(g, "ratio_coefficients_to_rgb", ratio(configs[coefficients16], configs[rgbAlbedo16]));
    nlohmann::json& st = j["still_camera_16"];
    st["median_ms"] = configs[still16].medianMs();
    putRatio(st, "ratio_to_moving", ratio(configs[still16], configs[moving16]));
    nlohmann::json& orb = j["orbiting_camera_16"];
    orb["degrees_per_frame"] = kOrbitDegPerFrame;
    orb["median_ms"] = configs[orbiting16].medianMs();
    orb["shadow_maps_per_frame"] = configs[orbiting16].shadowMapsPerFrame();
    orb["every_shadow_map_per_frame"] = configs[moving16].shadowMapsPerFrame();
    putRatio(orb, "ratio_to_every_shadow_map", ratio(configs[orbiting16], configs[moving16]));
    for (const auto& [strategy, i] : strategies16) {
      nlohmann::json& e = j["strategies_16"][std::string(samplingStrategyName(strategy))];
      e["median_ms"] = configs[i].medianMs();
      putRatio(e, "ratio_to_rotated", ratio(configs[i], configs[strategies16.front().second]));
    }
    for (const TechniqueRun& run : techniqueRuns) {
      nlohmann::json& t = j["techniques"][run.key];
      for (const auto& [label, i] : run.configs) t["median_ms"][label] = configs[i].medianMs();
      for (const TechniqueBenchRatio& r : run.ratios)
        putRatio(t, r.name, ratio(configs[run.configs.at(r.numerator)], configs[run.configs.at(r.denominator)]));
    }
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("{} at {}x{} on {}; GPU timer queries, {} rounds of {} frames per configuration (after {} warm-up "
             "each), the configurations interleaved; medians over the rounds, × RGB the median of the "
             "per-round ratios (its 95 % confidence interval) [lowest, highest round]\n",
             options.scene.string(), settings.width, settings.height, device, rounds, frames, options.warmup);
  std::vector<std::string> passes;
  for (const auto& [name, ms] : configs[rgb].medianMs()) {
    if (name != "frame") passes.push_back(name);
  }
  std::string header = fmt::format("{:>8} {:>10}", "mode", "frame ms");
  for (const std::string& p : passes) header += fmt::format(" {:>10}", p);
  header += fmt::format(" {:>9} {:>17} {:>15}", "× RGB", "95 % interval", "rounds");
  fmt::print("{}\n", header);
  auto confidence = [](const RatioSpread& s) {
    return std::isnan(s.confidence.low) ? std::string("(none: < 6 rounds)")
                                        : fmt::format("({:.3f}, {:.3f})", s.confidence.low, s.confidence.high);
  };
  auto row = [&](const Config& c) {
    std::string line = fmt::format("{:>8} {:>10.3f}", c.label, c.frameMs());
    for (const std::string& p : passes) line += fmt::format(" {:>10.3f}", c.passMs(p.c_str()));
    RatioSpread s = ratio(c, configs[rgb]);
    line += fmt::format(" {:>9.3f} {:>17} {:>15}", s.median, confidence(s), fmt::format("[{:.3f}, {:.3f}]", s.min, s.max));
    fmt::print("{}\n", line);
  };
  row(configs[rgb]);
  for (std::size_t i : spectral) row(configs[i]);
  if (spectral.size() > 1)
    fmt::print("fit: t(n) = {:.4f} ms·n + {:.3f} ms; slope = {:.2f} % of the RGB frame per wavelength\n", fit.slope,
               fit.intercept, 100.0 * fit.slope / rgbFrame);
  else
    fmt::print("fit: none (one wavelength count; give --wavelengths two or more for a slope)\n");
  fmt::print("GPU memory held by the renderer: RGB {:.2f} MiB, n = {} {:.2f} MiB (+{:.3f} MiB)\n",
             mebibytes(configs[rgb].gpuMemoryBytes), largest->wavelengths, mebibytes(largest->gpuMemoryBytes),
             mebibytes(largest->gpuMemoryBytes) - mebibytes(configs[rgb].gpuMemoryBytes));
  auto spread = [&](const RatioSpread& s) {
    return fmt::format("{:.3f}× {} [{:.3f}, {:.3f}]", s.median, confidence(s), s.min, s.max);
  };
  const Config& coefficients = configs[coefficients16];
  const Config& rgbAlbedoConfig = configs[rgbAlbedo16];
  fmt::print("G-buffer at 16 wavelengths, coefficients / RGB albedo: frame {:.3f} / {:.3f} ms = {} "
             "(G-buffer {:.3f} / {:.3f} ms, lighting {:.3f} / {:.3f} ms)\n",
             coefficients.frameMs(), rgbAlbedoConfig.frameMs(), spread(ratio(coefficients, rgbAlbedoConfig)),
             coefficients.passMs("gbuffer"), rgbAlbedoConfig.passMs("gbuffer"), coefficients.passMs("lighting"),
             rgbAlbedoConfig.passMs("lighting"));
  std::string strategyLine = "wavelength strategies at 16 wavelengths, frame / rotated's:";
  for (const auto& [strategy, i] : strategies16) {
    if (i == strategies16.front().second) continue;
    strategyLine += fmt::format(" {} {}", samplingStrategyName(strategy), spread(ratio(configs[i], configs[strategies16.front().second])));
  }
  fmt::print("{}\n", strategyLine);
  fmt::print("a still camera at 16 wavelengths (shadow maps and G-buffer kept while frames accumulate), frame / a "
             "restart's that draws them all again: {:.3f} / {:.3f} ms = {}\n",
             configs[still16].frameMs(), configs[moving16].frameMs(), spread(ratio(configs[still16], configs[moving16])));
  fmt::print("a camera orbiting {:g}° a frame under still lights at 16 wavelengths (shadow maps drawn again only where "
             "their view moved: {:.2f} a frame, against {:.2f}), frame / with every map drawn again: {:.3f} / {:.3f} ms "
             "= {} (shadow pass {:.3f} / {:.3f} ms)\n",
             kOrbitDegPerFrame, configs[orbiting16].shadowMapsPerFrame(), configs[moving16].shadowMapsPerFrame(),
             configs[orbiting16].frameMs(), configs[moving16].frameMs(), spread(ratio(configs[orbiting16], configs[moving16])),
             configs[orbiting16].passMs("shadow"), configs[moving16].passMs("shadow"));
  // Per technique, each ratio with its frames and, when the technique has a pass of its own
  // (named by its key), that pass's time in both.
  for (const TechniqueRun& run : techniqueRuns) {
    for (const TechniqueBenchRatio& r : run.ratios) {
      const Config& n = configs[run.configs.at(r.numerator)];
      const Config& d = configs[run.configs.at(r.denominator)];
      std::string line = fmt::format("{}: {} / {} frame {:.3f} / {:.3f} ms = {}", run.key, n.label, d.label,
                                     n.frameMs(), d.frameMs(), spread(ratio(n, d)));
      const double np = n.passMs(run.key.c_str()), dp = d.passMs(run.key.c_str());
      if (np > 0.0 || dp > 0.0) line += fmt::format(" ({} pass {:.3f} / {:.3f} ms)", run.key, np, dp);
      fmt::print("{}\n", line);
    }
  }
}

}  // namespace prism::harness

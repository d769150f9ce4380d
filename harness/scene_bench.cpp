#include "harness/scene_bench.h"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "gpu/headless_context.h"
#include "gpu/timer_query.h"
#include "harness/progress_bar.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/atomic_file.h"
#include "spectral/error.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::harness {
namespace {

struct ConfigResult {
  std::string label;  // "rgb" or the wavelength count
  int wavelengths = 0;  // 0 for RGB
  std::map<std::string, double> medianMs;  // per pass and "frame"
};

constexpr int kFramesInFlight = 3;  // the timer's ring

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

ConfigResult measure(render::Renderer& renderer, gpu::GpuTimer& timer, int warmup, int frames,
                     ProgressBar& bar, std::size_t& done, std::size_t total) {
  std::map<std::string, std::vector<double>> samples;
  auto collect = [&](const gpu::GpuTimings& timings) {
    for (const auto& [name, ms] : timings) samples[name].push_back(ms);
  };
  bool open = false;
  renderer.setPassHook([&](std::string_view pass) {
    if (open) timer.endScope();
    open = !pass.empty();
    if (open) timer.beginScope(pass);
  });
  // A frame's times arrive kFramesInFlight frames later: render that many more frames than are
  // timed, so that exactly `frames` frames after the warm-up are collected, none waited for.
  for (int f = 0; f < warmup + frames + kFramesInFlight; ++f) {
    timer.beginFrame();
    if (f >= warmup + kFramesInFlight) collect(timer.latest());
    renderer.renderFrame();
    timer.endFrame();
    if (f < warmup + frames) bar.update(++done, total);
  }
  renderer.setPassHook({});
  ConfigResult result;
  for (auto& [name, values] : samples) result.medianMs[name] = median(values);
  return result;
}

// Least squares t = a·n + b.
std::pair<double, double> linearFit(const std::vector<double>& n, const std::vector<double>& t) {
  double mn = 0, mt = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    mn += n[i];
    mt += t[i];
  }
  mn /= static_cast<double>(n.size());
  mt /= static_cast<double>(n.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    sxy += (n[i] - mn) * (t[i] - mt);
    sxx += (n[i] - mn) * (n[i] - mn);
  }
  double a = sxx > 0 ? sxy / sxx : 0.0;
  return {a, mt - a * mn};
}

std::string svgPlot(const std::vector<ConfigResult>& spectral, double rgbMs, double a, double b,
                    const std::string& title) {
  const double w = 640, h = 400, left = 70, right = 20, top = 40, bottom = 50;
  double maxN = 0, maxT = rgbMs;
  for (const ConfigResult& r : spectral) {
    maxN = std::max(maxN, static_cast<double>(r.wavelengths));
    maxT = std::max(maxT, r.medianMs.at("frame"));
  }
  maxT *= 1.1;
  auto x = [&](double n) { return left + n / maxN * (w - left - right); };
  auto y = [&](double t) { return h - bottom - t / maxT * (h - top - bottom); };
  std::ostringstream s;
  s << fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                   "font-family=\"sans-serif\" font-size=\"12\">\n", w, h);
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << fmt::format("<text x=\"{}\" y=\"22\" font-size=\"14\">{}</text>\n", left, title);
  s << fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>\n", left,
                   h - bottom, w - right);
  s << fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"black\"/>\n", left,
                   h - bottom, top);
  for (int i = 0; i <= 4; ++i) {
    double t = maxT * i / 4, n = maxN * i / 4;
    s << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{:.3g}</text>\n", left - 6,
                     y(t) + 4, t);
    s << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{:.0f}</text>\n", x(n),
                     h - bottom + 18, n);
  }
  s << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">wavelengths n</text>\n",
                   (left + w - right) / 2, h - 8);
  s << fmt::format("<text x=\"16\" y=\"{}\" transform=\"rotate(-90 16 {})\" "
                   "text-anchor=\"middle\">frame time (ms)</text>\n", (top + h - bottom) / 2,
                   (top + h - bottom) / 2);
  s << fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#c33\" "
                   "stroke-dasharray=\"6 4\"/>\n", x(0), y(rgbMs), x(maxN), y(rgbMs));
  s << fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#c33\" text-anchor=\"end\">RGB {:.3g} ms</text>\n",
                   w - right, y(rgbMs) - 6, rgbMs);
  s << fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#36c\"/>\n", x(0), y(b),
                   x(maxN), y(a * maxN + b));
  for (const ConfigResult& r : spectral) {
    s << fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"#36c\"/>\n",
                     x(r.wavelengths), y(r.medianMs.at("frame")));
  }
  s << fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#36c\">t(n) = {:.4g} ms·n + {:.4g} ms</text>\n",
                   left + 10, top + 14, a, b);
  s << "</svg>\n";
  return s.str();
}

}  // namespace

void runSceneBench(const SceneBenchOptions& options) {
  if (options.wavelengths.empty()) throw Error("--wavelengths: give at least one count");
  if (options.frames < 1 || options.warmup < 0) throw Error("--frames must be ≥ 1, --warmup ≥ 0");
  Scene scene = loadScene(options.scene);
  const render::FrameSettings& settings = options.settings;
  for (int n : options.wavelengths) {
    render::FrameSettings check = settings;
    check.sampling.count = n;
    render::validate(check);
  }
  RgbToSpectrumTable table = cachedRgbToSpectrumTable(scene.colourSpace, 64);
  gpu::HeadlessContext context;
  std::string device = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  render::Renderer renderer(scene, table, settings);
  gpu::GpuTimer timer({kFramesInFlight});

  std::size_t done = 0;
  // With a sky, the reference (118 batches of tables per frame) is timed over a few frames only.
  const int referenceFrames = std::min(options.frames, 3), referenceWarmup = std::min(options.warmup, 1);
  std::size_t total = (options.wavelengths.size() + 3 + (scene.water ? 3 : 0) + (scene.atmosphere ? 1 : 0)) *
                          static_cast<std::size_t>(options.warmup + options.frames) +
                      (scene.atmosphere ? static_cast<std::size_t>(referenceWarmup + referenceFrames) : 0);
  ProgressBar bar("benchmark " + options.scene.filename().string());
  ConfigResult rgb = measure(renderer, timer, options.warmup, options.frames, bar, done, total);
  rgb.label = "rgb";
  std::vector<ConfigResult> spectral;
  for (int n : options.wavelengths) {
    render::FrameSettings s = settings;
    s.mode = render::RenderMode::JakobHanika;
    s.sampling.count = n;
    renderer.setSettings(s);
    ConfigResult r = measure(renderer, timer, options.warmup, options.frames, bar, done, total);
    r.label = std::to_string(n);
    r.wavelengths = n;
    spectral.push_back(std::move(r));
  }

  // What the G-buffer keeps of a base colour (issue #4: which is faster?): RGB albedo, upsampled
  // once per pixel in the lighting pass, against Jakob–Hanika coefficients looked up per G-buffer
  // fragment into one more RGBA32F target; 16 wavelengths, the same run.
  render::FrameSettings rgbAlbedo = settings;
  rgbAlbedo.mode = render::RenderMode::JakobHanika;
  rgbAlbedo.sampling.count = 16;
  rgbAlbedo.gbufferAlbedo = render::GBufferAlbedo::Rgb;
  render::FrameSettings coefficientAlbedo = rgbAlbedo;
  coefficientAlbedo.gbufferAlbedo = render::GBufferAlbedo::Coefficients;
  renderer.setSettings(coefficientAlbedo);
  ConfigResult coefficients16 = measure(renderer, timer, options.warmup, options.frames, bar, done, total);
  renderer.setSettings(rgbAlbedo);
  ConfigResult rgbAlbedo16 = measure(renderer, timer, options.warmup, options.frames, bar, done, total);

  // Under water: the water term's cost, the same frames with the scene's water taken out (RGB and
  // 16 wavelengths), measured in the same run.
  std::optional<std::pair<ConfigResult, ConfigResult>> dry;
  if (scene.water) {
    Scene dryScene = scene;
    dryScene.water.reset();
    render::Renderer dryRenderer(dryScene, table, settings);
    ConfigResult dryRgb = measure(dryRenderer, timer, options.warmup, options.frames, bar, done, total);
    render::FrameSettings s16 = settings;
    s16.mode = render::RenderMode::JakobHanika;
    s16.sampling.count = 16;
    dryRenderer.setSettings(s16);
    ConfigResult dry16 = measure(dryRenderer, timer, options.warmup, options.frames, bar, done, total);
    renderer.setSettings(s16);
    ConfigResult wet16 = measure(renderer, timer, options.warmup, options.frames, bar, done, total);
    dry.emplace(std::move(dryRgb), std::move(dry16));
    dry->second.label = "16 dry";
    wet16.label = "16 wet";
    dry->first.medianMs["wet_frame_16"] = wet16.medianMs.at("frame");
  }

  // Under the sky (issue #8): García Liñán's four optimised wavelengths against RGB-3 (the rgb
  // configuration above) and against the reference, every table recomputed every frame.
  std::optional<std::pair<ConfigResult, ConfigResult>> sky;
  if (scene.atmosphere) {
    render::FrameSettings s = settings;
    s.mode = render::RenderMode::Optimised4;
    renderer.setSettings(s);
    ConfigResult optimised = measure(renderer, timer, options.warmup, options.frames, bar, done, total);
    s.mode = render::RenderMode::Reference;
    renderer.setSettings(s);
    ConfigResult reference = measure(renderer, timer, referenceWarmup, referenceFrames, bar, done, total);
    sky.emplace(std::move(optimised), std::move(reference));
  }

  std::vector<double> ns, ts;
  for (const ConfigResult& r : spectral) {
    ns.push_back(r.wavelengths);
    ts.push_back(r.medianMs.at("frame"));
  }
  auto [a, b] = linearFit(ns, ts);
  double rgbFrame = rgb.medianMs.at("frame");
  // GPU memory the spectral modes add over RGB: the upsampling table texture (RGB32F) and the
  // per-frame spectra buffers; render targets and meshes are the same in both modes.
  std::size_t res = static_cast<std::size_t>(table.resolution());
  double tableMb = static_cast<double>(res * res * res * 3 * 3 * sizeof(float)) / (1024.0 * 1024.0);
  std::size_t maxN = static_cast<std::size_t>(*std::max_element(options.wavelengths.begin(),
                                                                options.wavelengths.end()));
  std::size_t batches = maxN / 4;
  double buffersMb = static_cast<double>(batches * (sizeof(shared::GpuBatch) +
                                                    (scene.lights.size() + 1) * 16 +
                                                    scene.materials.size() * 32)) /
                     (1024.0 * 1024.0);

  if (!options.plot.empty()) {
    writeFileAtomically(options.plot,
                        svgPlot(spectral, rgbFrame, a, b,
                                fmt::format("{} at {}x{} on {}", options.scene.filename().string(),
                                            settings.width, settings.height, device)));
  }
  if (options.json) {
    nlohmann::json j;
    j["scene"] = options.scene.string();
    j["device"] = device;
    j["width"] = settings.width;
    j["height"] = settings.height;
    j["frames"] = options.frames;
    j["rgb"] = rgb.medianMs;
    for (const ConfigResult& r : spectral) {
      nlohmann::json c;
      c["wavelengths"] = r.wavelengths;
      c["median_ms"] = r.medianMs;
      c["ratio_to_rgb"] = r.medianMs.at("frame") / rgbFrame;
      j["spectral"].push_back(c);
    }
    j["fit"] = {{"slope_ms_per_wavelength", a}, {"intercept_ms", b},
                {"slope_fraction_of_rgb_frame", a / rgbFrame}};
    j["extra_gpu_memory_mb"] = {{"upsampling_table", tableMb}, {"frame_buffers", buffersMb}};
    j["gbuffer_albedo_16"] = {{"rgb_frame_ms", rgbAlbedo16.medianMs.at("frame")},
                              {"coefficients_frame_ms", coefficients16.medianMs.at("frame")},
                              {"rgb_median_ms", rgbAlbedo16.medianMs},
                              {"coefficients_median_ms", coefficients16.medianMs},
                              {"ratio_coefficients_to_rgb",
                               coefficients16.medianMs.at("frame") / rgbAlbedo16.medianMs.at("frame")}};
    if (dry) {
      j["water"] = {{"rgb_ratio_wet_to_dry", rgbFrame / dry->first.medianMs.at("frame")},
                    {"spectral16_ratio_wet_to_dry",
                     dry->first.medianMs.at("wet_frame_16") / dry->second.medianMs.at("frame")},
                    {"dry_rgb_frame_ms", dry->first.medianMs.at("frame")},
                    {"dry_spectral16_frame_ms", dry->second.medianMs.at("frame")},
                    {"wet_spectral16_frame_ms", dry->first.medianMs.at("wet_frame_16")}};
    }
    if (sky) {
      j["sky"] = {{"optimised4_median_ms", sky->first.medianMs},
                  {"reference_median_ms", sky->second.medianMs},
                  {"reference_frames", referenceFrames},
                  {"ratio_optimised4_to_rgb3", sky->first.medianMs.at("frame") / rgbFrame},
                  {"ratio_reference_to_optimised4", sky->second.medianMs.at("frame") / sky->first.medianMs.at("frame")}};
    }
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("{} at {}x{} on {}; median of {} frames after {} warm-up, GPU timer queries\n",
             options.scene.string(), settings.width, settings.height, device, options.frames,
             options.warmup);
  std::vector<std::string> passes;
  for (const auto& [name, ms] : rgb.medianMs) {
    if (name != "frame") passes.push_back(name);
  }
  std::string header = fmt::format("{:>8} {:>10}", "mode", "frame ms");
  for (const std::string& p : passes) header += fmt::format(" {:>10}", p);
  header += fmt::format(" {:>9}", "× RGB");
  fmt::print("{}\n", header);
  auto row = [&](const ConfigResult& r) {
    std::string line = fmt::format("{:>8} {:>10.3f}", r.label, r.medianMs.at("frame"));
    for (const std::string& p : passes) {
      auto it = r.medianMs.find(p);
      line += fmt::format(" {:>10.3f}", it == r.medianMs.end() ? 0.0 : it->second);
    }
    line += fmt::format(" {:>9.3f}", r.medianMs.at("frame") / rgbFrame);
    fmt::print("{}\n", line);
  };
  row(rgb);
  for (const ConfigResult& r : spectral) row(r);
  fmt::print("fit: t(n) = {:.4f} ms·n + {:.3f} ms; slope = {:.2f} % of the RGB frame per wavelength\n",
             a, b, 100.0 * a / rgbFrame);
  fmt::print("GPU memory added by spectral modes: {:.2f} MB (upsampling table {:.2f} MB, "
             "frame buffers at n = {} {:.3f} MB)\n", tableMb + buffersMb, tableMb, maxN, buffersMb);
  auto passMs = [](const ConfigResult& r, const char* pass) {
    auto it = r.medianMs.find(pass);
    return it == r.medianMs.end() ? 0.0 : it->second;
  };
  fmt::print("G-buffer at 16 wavelengths, coefficients / RGB albedo: frame {:.3f} / {:.3f} ms = {:.3f}× "
             "(G-buffer {:.3f} / {:.3f} ms, lighting {:.3f} / {:.3f} ms)\n",
             coefficients16.medianMs.at("frame"), rgbAlbedo16.medianMs.at("frame"),
             coefficients16.medianMs.at("frame") / rgbAlbedo16.medianMs.at("frame"), passMs(coefficients16, "gbuffer"),
             passMs(rgbAlbedo16, "gbuffer"), passMs(coefficients16, "lighting"), passMs(rgbAlbedo16, "lighting"));
  if (dry) {
    double wet16 = dry->first.medianMs.at("wet_frame_16"), dry16 = dry->second.medianMs.at("frame");
    fmt::print("water on / off: RGB {:.3f} / {:.3f} ms = {:.3f}×; 16 wavelengths {:.3f} / {:.3f} ms = {:.3f}×\n",
               rgbFrame, dry->first.medianMs.at("frame"), rgbFrame / dry->first.medianMs.at("frame"), wet16,
               dry16, wet16 / dry16);
  }
  if (sky) {
    auto atmosphereMs = [&](const ConfigResult& r) { return passMs(r, "atmosphere"); };
    double optimised = sky->first.medianMs.at("frame"), reference = sky->second.medianMs.at("frame");
    fmt::print("sky: optimised4 / RGB-3 frame {:.3f} / {:.3f} ms = {:.3f}× (sky tables {:.3f} / {:.3f} ms); "
               "reference (472 wavelengths, {} frames) {:.3f} ms = {:.1f}× optimised4 (sky tables {:.3f} ms)\n",
               optimised, rgbFrame, optimised / rgbFrame, atmosphereMs(sky->first), atmosphereMs(rgb), referenceFrames,
               reference, reference / optimised, atmosphereMs(sky->second));
  }
}

}  // namespace prism::harness

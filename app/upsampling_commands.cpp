#include "app/upsampling_commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "harness/progress_bar.h"
#include "spectral/colour_space.h"
#include "app/option_error.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/task_split.h"
#include "spectral/rgb_intent.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/rgb_to_spectrum_optimiser.h"
#include "spectral/rgb_to_spectrum_part.h"
#include "spectral/rgb_to_spectrum_quality.h"
#include "spectral/spectrum.h"

namespace prism::app {
namespace {

// How many wavelengths `upsample` prints at most: every 0.01 nm over 360–830 nm.
constexpr double kMaxUpsampledWavelengths = 47001;

using nlohmann::json;

json errorJson(const UpsamplingError& e) {
  return {{"count", e.count},
          {"rmsDeltaE2000", e.rmsDeltaE2000},
          {"maxDeltaE2000", e.maxDeltaE2000},
          {"fractionWithinDeltaE1", e.fractionWithin1},
          {"worstRgb", {e.worstRgb.x, e.worstRgb.y, e.worstRgb.z}},
          {"reflectanceRange", {e.minReflectance, e.maxReflectance}}};
}

void printError(const char* what, const UpsamplingError& e) {
  fmt::print("{:<28} n={:<8} RMS ΔE00 {:.5f}  max {:.4f}  ≤1: {:.4f}%  reflectance [{:.3g}, {:.6f}]  worst rgb ({:.4f}, {:.4f}, {:.4f})\n",
             what, e.count, e.rmsDeltaE2000, e.maxDeltaE2000, 100.0 * e.fractionWithin1,
             e.minReflectance, e.maxReflectance, e.worstRgb.x, e.worstRgb.y, e.worstRgb.z);
}

// Task I of N's columns of the table, as a part for `prism merge`.
void runLutPart(const LutOptions& o, const std::string& gamut) {
  if (o.report || o.json) throw Error("--report, --json: measure the merged table (prism lut --part writes a part)");
  const TaskIndex task = parseTaskIndex(o.part, "--part");
  const int columns = tableColumns(o.resolution);
  if (task.count > columns) {
    throw Error(fmt::format("--part {}: the {}³ table has {} columns, at most {} tasks", o.part, o.resolution, columns,
                            columns));
  }
  const IndexRange share = shareOf(task, columns);
  const std::string what = fmt::format("columns {}:{} of {}", share.begin, share.end, columns);
  if (isTablePart(o.output)) {
    try {
      RgbToSpectrumPart existing = loadTablePart(o.output);
      if (existing.gamut == gamut && existing.resolution == o.resolution && existing.columns == share) {
        fmt::print("{}: complete ({}), skipped\n", o.output, what);
        return;
      }
    } catch (const Error& e) {
      fmt::print("{}: building it again ({})\n", o.output, e.what());
    }
  }
  requireWritable(o.output);
  harness::ProgressBar bar(fmt::format("lut {} {}³ part {}", gamut, o.resolution, o.part));
  RgbToSpectrumTable table = buildRgbToSpectrumTable(
      {gamut, o.resolution, o.threads, [&](std::size_t done, std::size_t total) { bar.update(done, total); }}, share);
  saveTablePart(o.output, tablePart(table, share));
  fmt::print("wrote {} ({} table, {})\n", o.output, gamut, what);
}

}  // namespace

void runLut(const LutOptions& o) {
  const std::string gamut = fromOption("--gamut", [&] { return colourSpace(o.gamut).name; });  // before any work
  fromOption("--res", [&] { requireBuildableResolution(o.resolution); });
  if (o.output.empty()) throw Error("lut: give the output file with -o");
  refuseImageExtension(o.output, "-o", o.part.empty() ? "upsampling table" : "part of an upsampling table");
  if (!o.part.empty()) {
    runLutPart(o, gamut);
    return;
  }
  requireWritable(o.output);
  harness::ProgressBar bar("lut " + gamut + " " + std::to_string(o.resolution) + "³");
  auto start = std::chrono::steady_clock::now();
  RgbToSpectrumTable table = buildRgbToSpectrumTable(
      {gamut, o.resolution, o.threads, [&](std::size_t done, std::size_t total) { bar.update(done, total); }});
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  table.save(o.output);
  json out = {{"gamut", gamut}, {"resolution", o.resolution}, {"file", o.output}, {"buildSeconds", seconds}};
  if (o.report) {
    out["nodes"] = errorJson(nodeError(table, o.threads));
    out["roundTripManual"] = errorJson(roundTripError(table, LookupPath::Manual, 100000, 1, o.threads));
    out["roundTripFiltered"] = errorJson(roundTripError(table, LookupPath::Filtered, 100000, 1, o.threads));
  }
  if (o.json) {
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("{}: {} table, {}³ × 3 blocks, built in {:.1f} s\n", o.output, gamut, o.resolution, seconds);
  if (o.report) {
    printError("nodes (no interpolation)", nodeError(table, o.threads));
    printError("round trip, manual", roundTripError(table, LookupPath::Manual, 100000, 1, o.threads));
    printError("round trip, filtered", roundTripError(table, LookupPath::Filtered, 100000, 1, o.threads));
  }
}

void runUpsample(const UpsampleOptions& o) {
  if (o.rgb.size() != 3) throw Error("--rgb: expected three comma-separated numbers");
  if (o.wavelengths.size() != 3 || !(o.wavelengths[2] > 0.0) || !(o.wavelengths[0] <= o.wavelengths[1]) ||
      o.wavelengths[0] < kLambdaMinNm || o.wavelengths[1] > kLambdaMaxNm)
    throw Error("--wavelengths: expected MIN:MAX:STEP in nm within 360–830 with MIN ≤ MAX and STEP > 0");
  if ((o.wavelengths[1] - o.wavelengths[0]) / o.wavelengths[2] > kMaxUpsampledWavelengths)
    throw Error(fmt::format("--wavelengths: at most {} wavelengths (a STEP of {} nm gives more)", kMaxUpsampledWavelengths,
                            o.wavelengths[2]));
  if (o.intent != "albedo" && o.intent != "unbounded")
    throw Error("--intent: unknown intent '" + o.intent + "' (albedo, unbounded)");
  const std::string path = o.path.value_or("manual");
  if (path != "manual" && path != "filtered")
    throw Error("--path: unknown lookup path '" + path + "' (manual, filtered)");
  if (o.method != "jakob-hanika" && o.method != "box")
    throw Error("--method: unknown method '" + o.method + "' (jakob-hanika, box)");
  if (o.method == "box" && (o.path || o.resolution || o.gamut))
    throw Error(
        "--method box splits RGB into fixed bands with no table: --path, --res and --gamut are for jakob-hanika");
  if (o.intent == "unbounded" && path != "manual")
    throw Error("--path " + path + ": the unbounded intent looks its scaled albedo up the manual way only");
  const std::string gamut = fromOption("--gamut", [&] { return colourSpace(o.gamut.value_or("srgb")).name; });
  if (o.resolution) fromOption("--res", [&] { requireBuildableResolution(*o.resolution); });
  glm::vec3 rgb(static_cast<float>(o.rgb[0]), static_cast<float>(o.rgb[1]), static_cast<float>(o.rgb[2]));
  glm::vec3 coeffs(0.0f);
  float scale = 1.0f;
  Spectrum reflectance;
  if (o.method == "box") {
    if (o.intent == "unbounded") {
      scale = std::max({rgb.x, rgb.y, rgb.z, 0.0f});
      rgb = scale > 0.0f ? rgb / scale : glm::vec3(0.0f);
    }
    reflectance = boxReflectanceSpectrum(rgb);
  } else {
    harness::ProgressBar bar("building the " + gamut + " upsampling table (first use, cached)");
    RgbToSpectrumTable table =
        cachedRgbToSpectrumTable(gamut, o.resolution.value_or(kRendererTableResolution),
                                 [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    if (o.intent == "unbounded") {
      RgbUnboundedSpectrum u(table, rgb);
      coeffs = u.coefficients(), scale = u.scale();
    } else {
      coeffs = path == "manual" ? table.lookup(rgb) : table.lookupFiltered(rgb);
    }
    reflectance = upsampledReflectanceSpectrum(coeffs);
  }
  json spectrum = json::array();
  for (double l = o.wavelengths[0]; l <= o.wavelengths[1] + 1e-9; l += o.wavelengths[2])
    spectrum.push_back({l, scale * reflectance.at(l)});
  if (o.json) {
    fmt::print("{}\n", json{{"rgb", o.rgb}, {"gamut", gamut}, {"method", o.method}, {"intent", o.intent}, {"path", path},
                            {"coefficients", {coeffs.x, coeffs.y, coeffs.z}}, {"scale", scale},
                            {"spectrum", spectrum}}
                           .dump(2));
    return;
  }
  fmt::print("coefficients {:.8g} {:.8g} {:.8g}  scale {:.6g}\nwavelength_nm,value\n", coeffs.x,
             coeffs.y, coeffs.z, scale);
  for (const json& row : spectrum) fmt::print("{},{:.6f}\n", row[0].get<double>(), row[1].get<double>());
}

}  // namespace prism::app

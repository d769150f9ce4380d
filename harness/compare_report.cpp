#include "harness/compare_report.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Core>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "imaging/exr_file.h"
#include "imaging/heatmap.h"
#include "imaging/image_difference.h"
#include "imaging/png_file.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/json_schema.h"

namespace prism::harness {
namespace {

// The dimmest display white taken (cd/m²): below the dimmest Prism writes (EV100 −50: 1.2·2⁻⁵⁰,
// 1.1e-15), above what overflows CIELAB (a white of 1e-40 put every colour at L* = inf).
constexpr double kMinWhite = 1e-20;

// One side of the comparison, kept alive while the input views it.
struct Loaded {
  imaging::PngImage png;
  imaging::ExrImage exr;
  bool linear = false;
  imaging::DifferenceInput input() const {
    if (!linear) return imaging::png8Input(png);
    const double white = exr.displayWhite.value_or(1.0);
    return exr.camera ? imaging::cameraInput(exr.image, exr.camera->toXyz, white)
                      : imaging::linearInput(exr.image, exr.colour, white);
  }
};

// What makes an image of that meaning one compare takes, for its refusal.
std::string_view colourRemedy(imaging::ColourMeaning colour) {
  switch (colour) {
    case imaging::ColourMeaning::Xyz1964: return "render it with --observer cie1931";
    case imaging::ColourMeaning::OtherRgb:
      return "RGB of primaries Prism does not know: a nebula's filter palette (nebula render --filters cie1931 "
             "writes XYZ), a reference's --variance (squared units, no colour) or a foreign EXR";
    case imaging::ColourMeaning::Xyz:
    case imaging::ColourMeaning::LinearSrgb:
    case imaging::ColourMeaning::CameraRgb: break;  // taken (a camera's with its matrix: requireCamera)
  }
  PRISM_CHECK(false);
  return "";
}

// A camera's raw RGB is compared in CIE 1931 XYZ through the matrix its frame is shown through,
// which the file records: the camera's ColorChecker fit under the scene's light. Each side
// through its own, so that one camera under two lights, two cameras, or a camera against the
// eye's XYZ compare as each frame shows its scene (the difference then holds the cameras' own
// colour errors: what a camera sees against what the eye does).
void requireCamera(const std::filesystem::path& path, const imaging::ExrImage& exr) {
  if (!exr.camera)
    throw Error(fmt::format("{}: a camera's raw RGB that does not say which camera and matrix ({}, {}): render it "
                            "again with this Prism", path.string(), imaging::kCameraAttribute,
                            imaging::kCameraToXyzAttribute));
}

// What a side holds, as the report names it.
std::string holds(const Loaded& l) {
  return l.exr.camera ? l.exr.camera->name + "'s raw RGB" : std::string(imaging::colourMeaningName(l.exr.colour)) + " values";
}

Loaded load(const std::filesystem::path& path, const std::optional<double>& white) {
  Loaded l;
  std::string extension = lowercaseExtension(path);
  if (extension == ".exr") {
    l.linear = true;
    l.exr = imaging::readExr(path);
    if (l.exr.colour != imaging::ColourMeaning::Xyz && l.exr.colour != imaging::ColourMeaning::LinearSrgb &&
        l.exr.colour != imaging::ColourMeaning::CameraRgb) {
      throw Error(fmt::format("{}: holds {} values; compare takes CIE 1931 XYZ, linear sRGB or a camera's RGB ({})", path.string(),
                              imaging::colourMeaningName(l.exr.colour), colourRemedy(l.exr.colour)));
    }
    // A reference render's part: a band of rows (the rest of the image left out), or some of each
    // pixel's paths under another exposure's white; compared as it stands, its numbers meant nothing.
    if (l.exr.part)
      throw Error(fmt::format("{}: a part of a reference render; merge the parts first (prism merge)", path.string()));
    if (l.exr.image.channels < 3)
      throw Error(fmt::format("{}: a lone Y channel (luminance alone); compare takes colour (R, G, B or X, Y, Z), "
                              "which CIEDE2000 needs", path.string()));
    if (!l.exr.wholeImage)
      throw Error(fmt::format("{}: its data window is not its display window (a crop or an overscan); compare takes "
                              "whole images", path.string()));
    if (white) l.exr.displayWhite = *white;  // checked by the caller
    else if (l.exr.displayWhite && !(*l.exr.displayWhite >= kMinWhite))
      throw Error(fmt::format("{}: {} {:g} is below {:g}: CIELAB against so dim a white overflows", path.string(),
                              imaging::kDisplayWhiteAttribute, *l.exr.displayWhite, kMinWhite));
    if (imaging::NonFinitePixels bad = imaging::nonFinitePixels(l.exr.image); bad.count > 0) {
      throw Error(fmt::format("{}: pixel ({}, {}) holds {}: compare takes finite images", path.string(), bad.firstX,
                              bad.firstY, bad.firstValue));
    }
    if (l.exr.colour == imaging::ColourMeaning::CameraRgb) requireCamera(path, l.exr);
  } else {
    l.png = imaging::readPng8(path);
  }
  return l;
}

}  // namespace

void runCompare(const CompareOptions& o) {
  const auto within = [](double v, double lo) { return v >= lo && v <= schema::kFloatInputLimit; };
  if (o.white && !within(*o.white, kMinWhite))
    throw Error(fmt::format("--white: must be a luminance within {:g}–{:g}", kMinWhite, schema::kFloatInputLimit));
  if (!within(o.threshold, 0.0)) throw Error(fmt::format("--threshold: must be within 0–{:g}", schema::kFloatInputLimit));
  const double scaleMax = o.scaleMax.value_or(10.0);
  if (!(scaleMax > 0.0 && within(scaleMax, 0.0)))
    throw Error(fmt::format("--scale-max: must be > 0 and up to {:g}", schema::kFloatInputLimit));
  if (o.scaleMax && o.heatmap.empty() && o.histogram.empty())
    throw Error("--scale-max: only with --heatmap or --histogram, whose scale it sets");
  for (const auto& [option, path] : {std::pair{"--heatmap", &o.heatmap}, std::pair{"--histogram", &o.histogram}}) {
    if (!path->empty()) requireExtension(*path, ".png", option, "picture");
    requireOtherFile(*path, o.reference, "the reference image");
    requireOtherFile(*path, o.test, "the test image");
  }
  requireOtherFile(o.histogram, o.heatmap, "the heat map");
  // Both outputs writable before either is written: a histogram refused after the heat map left it.
  for (const std::filesystem::path& output : {o.heatmap, o.histogram})
    if (!output.empty()) requireWritable(output);
  Loaded reference = load(o.reference, o.white);
  Loaded test = load(o.test, o.white);
  // Linear light against a display image (tone-mapped, exposed, encoded) measures the display
  // transform, not the renders: refused, as is a white for two display images.
  if (reference.linear != test.linear)
    throw Error(fmt::format("{} is {} and {} {}: compare two EXRs (linear light) or two PNGs (display images)",
                            o.reference.string(), reference.linear ? "an EXR" : "a PNG", o.test.string(),
                            test.linear ? "an EXR" : "a PNG"));
  if (o.white && !reference.linear) throw Error("--white: only for EXRs; a PNG's white is the display's");
  // Both linear sides must be put into CIELAB against one white: the one they agree on, the one
  // only one of them records, or --white.
  if (reference.linear && test.linear && !o.white) {
    std::optional<double>& a = reference.exr.displayWhite;
    std::optional<double>& b = test.exr.displayWhite;
    if (a && b && std::abs(*a - *b) > 1e-4 * std::max(*a, *b)) {
      throw Error(fmt::format("{} and {} were exposed for different display whites ({:g} and {:g} cd/m²); "
                              "give --white to compare them against one", o.reference.string(),
                              o.test.string(), *a, *b));
    }
    if (!a) a = b;
    if (!b) b = a;
  }
  imaging::DifferenceOptions options;
  options.thresholdDeltaE = o.threshold;
  options.keepMap = !o.heatmap.empty() || !o.histogram.empty();
  imaging::ImageDifference difference;
  try {
    difference = imaging::compareImages(reference.input(), test.input(), options);
  } catch (const Error& e) {
    throw Error(fmt::format("{} vs {}: {}", o.reference.string(), o.test.string(), e.what()));
  }
  if (!o.heatmap.empty()) {
    imaging::heatMap(difference.deltaEMap, {.maxDeltaE = scaleMax, .legend = true}).write(o.heatmap);
  }
  if (!o.histogram.empty()) {
    imaging::HistogramOptions h;
    h.maxDeltaE = scaleMax;
    imaging::deltaEHistogram(difference.deltaEMap, h).write(o.histogram);
  }
  const imaging::DifferenceStats& s = difference.stats;
  if (o.json) {
    nlohmann::json j = {{"reference", o.reference.string()}, {"test", o.test.string()},
                        {"pixels", s.pixelCount},        {"mean_delta_e", s.meanDeltaE},
                        {"median_delta_e", s.medianDeltaE}, {"p95_delta_e", s.p95DeltaE},
                        {"p99_delta_e", s.p99DeltaE},     {"max_delta_e", s.maxDeltaE},
                        {"threshold_delta_e", s.thresholdDeltaE}, {"fraction_above", s.fractionAbove},
                        {"mae_8bit", s.mae8},             {"relative_error", s.relativeError}};
    if (reference.exr.camera) j["reference_camera"] = reference.exr.camera->name;
    if (test.exr.camera) j["test_camera"] = test.exr.camera->name;
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("{} vs {} ({} pixels)\n", o.reference.string(), o.test.string(), s.pixelCount);  // as given, as errors say
  if (reference.exr.camera || test.exr.camera)
    fmt::print("{} against {}, compared in CIE 1931 XYZ: a camera's through the matrix its file records ({})\n",
               holds(reference), holds(test), imaging::kCameraToXyzAttribute);
  fmt::print("CIEDE2000  mean {:.4f}  median {:.4f}  p95 {:.4f}  p99 {:.4f}  max {:.4f}\n", s.meanDeltaE,
             s.medianDeltaE, s.p95DeltaE, s.p99DeltaE, s.maxDeltaE);
  fmt::print("pixels above ΔE00 {:g}: {:.2f} %\n", s.thresholdDeltaE, 100.0 * s.fractionAbove);
  fmt::print("MAE (8-bit sRGB) {:.4f}   relative error (linear) {:.4f}\n", s.mae8, s.relativeError);
}

}  // namespace prism::harness

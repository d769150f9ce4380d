// Comparing two images of the same size as a viewer would see them: per-pixel CIEDE2000
// (CIE 142:2001; Sharma, Wu & Dalal 2005) against a D65 white of Y = 1, summarised as mean,
// median, P95, P99 and max ΔE00 and the fraction of pixels above a threshold (STYLE.md §9), plus
// two plain numbers that the literature reports: MAE on 8-bit sRGB, as Pérez García's thesis
// does, and the mean relative error on linear values.
//
// Every input goes to the same three forms per pixel:
//   XYZ / Y_white       for ΔE00 (CIELAB with the sRGB D65 white; no chromatic adaptation, so
//                       XYZ input should already be relative to a D65-ish white)
//   linear sRGB         for the relative error (white = 1; may be negative out of gamut)
//   8-bit sRGB          for the MAE (raw bytes for 8-bit sRGB input; other input clipped to [0, 1],
//                       sRGB-encoded and rounded)
// 8-bit input is decoded with its colour space's exact transfer and matrix (the PNG's own: sRGB,
// Display P3 or Rec.2020); alpha is ignored everywhere.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include <Eigen/Core>

#include "imaging/float_image.h"
#include "imaging/png_file.h"

namespace prism::imaging {

// One side of a comparison: a view (the image must outlive the call). Make it with png8Input()
// or linearInput().
struct DifferenceInput {
  const PngImage* srgb8 = nullptr;                   // 8-bit display-encoded (PngImage::colourSpace), or
  const FloatImage* linear = nullptr;                // a linear image with 3 or 4 channels, and then:
  ColourMeaning colour = ColourMeaning::LinearSrgb;  // LinearSrgb, Xyz or CameraRgb (others are an Error)
  double whiteLuminance = 1.0;  // the value of white: Y_white for XYZ (e.g. in cd/m²), R=G=B for sRGB
  // CameraRgb's into CIE 1931 XYZ (render::cameraToXyz, which its EXRs record: ExrCamera); a
  // camera's RGB without it is an Error (make it with cameraInput).
  std::optional<Eigen::Matrix3d> cameraToXyz = std::nullopt;
};
inline DifferenceInput png8Input(const PngImage& image) { return {.srgb8 = &image}; }
inline DifferenceInput linearInput(const FloatImage& image, ColourMeaning colour,
                                   double whiteLuminance = 1.0) {
  return {.linear = &image, .colour = colour, .whiteLuminance = whiteLuminance};
}
// A camera's raw RGB, compared in CIE 1931 XYZ through its matrix.
inline DifferenceInput cameraInput(const FloatImage& image, const Eigen::Matrix3d& cameraToXyz,
                                   double whiteLuminance = 1.0) {
  return {.linear = &image, .colour = ColourMeaning::CameraRgb, .whiteLuminance = whiteLuminance,
          .cameraToXyz = cameraToXyz};
}

struct DifferenceOptions {
  double thresholdDeltaE = 1.0;   // for fractionAbove; ΔE00 ≈ 1 is the usual just-noticeable step
  double relativeEpsilon = 0.01;  // floor of |reference| in the relative error, in units of white
  bool keepMap = false;           // fill ImageDifference::deltaEMap
  unsigned threads = 0;           // 0: all hardware threads (results do not depend on it)
};

struct DifferenceStats {
  std::size_t pixelCount = 0;
  // ΔE00 over pixels. Percentiles interpolate linearly between order statistics (Hyndman & Fan
  // 1996, definition 7, numpy's default). A pixel whose ΔE is not finite (NaN or ∞ in an input)
  // counts as +∞, so it can only make an image fail.
  double meanDeltaE = 0.0;
  double medianDeltaE = 0.0;
  double p95DeltaE = 0.0;
  double p99DeltaE = 0.0;
  double maxDeltaE = 0.0;
  double thresholdDeltaE = 0.0;  // the threshold fractionAbove counted against
  double fractionAbove = 0.0;    // of pixels with ΔE00 > thresholdDeltaE
  double mae8 = 0.0;             // mean |a − b| over pixels and R, G, B of 8-bit sRGB, in 0..255
  double relativeError = 0.0;    // mean |a − b| / max(|a|, ε) over pixels and channels, linear sRGB
};

struct ImageDifference {
  DifferenceStats stats;
  FloatImage deltaEMap;  // 1 channel of ΔE00 when DifferenceOptions::keepMap, else empty
};

// `reference` is a in the formulas above. Error naming both sizes when they differ; Error when a
// linear input is neither linear sRGB nor XYZ, has 1 channel, or has a white luminance ≤ 0.
ImageDifference compareImages(const DifferenceInput& reference, const DifferenceInput& test,
                              const DifferenceOptions& options = {});

// The ΔE00 part of DifferenceStats from per-pixel values (mae8 and relativeError left 0).
DifferenceStats deltaEStats(std::span<const float> deltaE, double thresholdDeltaE);

// Percentile p ∈ [0, 1] of ascending `sorted` values, interpolated as in DifferenceStats.
double percentileOfSorted(std::span<const float> sorted, double p);

}  // namespace prism::imaging

// Linear floating-point images, the currency of the imaging layer: what EXR files hold, what
// renders are compared in, and single-channel maps such as the per-pixel ΔE of a comparison.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "spectral/observer.h"

namespace prism::imaging {

// What the three colour channels of a linear image mean. Written into EXR headers as the string
// attribute "prism:colour" with the names below.
enum class ColourMeaning {
  LinearSrgb,  // "linear-srgb": BT.709 primaries, D65 white, no transfer curve
  Xyz,         // "xyz": CIE 1931 XYZ, on whatever scale the producer chose (absolute or Y_white = 1)
  Xyz1964,     // "xyz-1964": CIE 1964 X₁₀Y₁₀Z₁₀ (the 10° observer), on the producer's scale
  CameraRgb,   // "camera-rgb": a sensor's raw RGB, not colorimetric without its camera matrix
  OtherRgb,    // "other-rgb": RGB with primaries Prism does not interpret (a foreign EXR)
};
std::string_view colourMeaningName(ColourMeaning colour);
// Error listing the known names when `name` is none of them.
ColourMeaning colourMeaningFromName(std::string_view name);
// What a tristimulus under `observer` means: XYZ for CIE 1931, X₁₀Y₁₀Z₁₀ for CIE 1964, a camera's
// raw RGB for a camera. (An RGB-mode frame's tristimulus is CIE 1931 XYZ whatever its observer.)
ColourMeaning tristimulusMeaning(const Observer& observer);

struct FloatImage {
  int width = 0;
  int height = 0;
  int channels = 3;           // 3 (RGB or XYZ), 4 (alpha last) or 1 (a scalar map such as ΔE)
  std::vector<float> pixels;  // width × height × channels, interleaved, row 0 at the top

  FloatImage() = default;
  // PRISM_CHECKs that the size is not negative and channels is 1, 3 or 4.
  FloatImage(int width, int height, int channels, float fill = 0.0f);

  std::size_t pixelCount() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  // No bounds check: this is the inner loop of every pass over an image.
  std::size_t index(int x, int y, int c) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
               static_cast<std::size_t>(channels) +
           static_cast<std::size_t>(c);
  }
  float& at(int x, int y, int c) { return pixels[index(x, y, c)]; }
  float at(int x, int y, int c) const { return pixels[index(x, y, c)]; }
};

// The pixels of an image that hold a NaN or an infinity in any channel: how many, and the first
// (row-major) with its first such value. What refuses to write a render (app/render_commands.cpp)
// or to compare an image (harness/compare_report.cpp) that the float pipeline did not carry.
struct NonFinitePixels {
  std::size_t count = 0;
  int firstX = -1;
  int firstY = -1;
  float firstValue = 0.0f;
};
NonFinitePixels nonFinitePixels(const FloatImage& image);

// Every input is checked finite and within what floats carry (core/json_schema.h); a frame that
// still overflows is refused rather than written with holes in it: Error "OUTPUT: not written: N
// of M pixels came out non-finite (the first, (X, Y), holds V)…" when the image holds any.
void requireFiniteOutput(const FloatImage& image, std::string_view output);

}  // namespace prism::imaging

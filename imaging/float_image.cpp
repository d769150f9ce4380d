#include "imaging/float_image.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace prism::imaging {
namespace {

struct NamedMeaning {
  ColourMeaning colour;
  std::string_view name;
};
constexpr NamedMeaning kMeanings[] = {
    {ColourMeaning::LinearSrgb, "linear-srgb"},
    {ColourMeaning::Xyz, "xyz"},
    {ColourMeaning::Xyz1964, "xyz-1964"},
    {ColourMeaning::CameraRgb, "camera-rgb"},
    {ColourMeaning::OtherRgb, "other-rgb"},
};

}  // namespace

std::string_view colourMeaningName(ColourMeaning colour) {
  for (const NamedMeaning& m : kMeanings)
    if (m.colour == colour) return m.name;
  PRISM_CHECK(false && "every ColourMeaning has a name");
  return {};
}

ColourMeaning colourMeaningFromName(std::string_view name) {
  for (const NamedMeaning& m : kMeanings)
    if (m.name == name) return m.colour;
  throw Error("unknown colour meaning '" + std::string(name) +
              "' (known: linear-srgb, xyz, xyz-1964, camera-rgb, other-rgb)");
}

ColourMeaning tristimulusMeaning(const Observer& observer) {
  if (observer.isCamera) return ColourMeaning::CameraRgb;
  return observer.name == "cie1964" ? ColourMeaning::Xyz1964 : ColourMeaning::Xyz;
}

FloatImage::FloatImage(int width_, int height_, int channels_, float fill)
    : width(width_), height(height_), channels(channels_) {
  PRISM_CHECK(width >= 0 && height >= 0);
  PRISM_CHECK(channels == 1 || channels == 3 || channels == 4);
  pixels.assign(pixelCount() * static_cast<std::size_t>(channels), fill);
}

NonFinitePixels nonFinitePixels(const FloatImage& image) {
  NonFinitePixels found;
  const std::size_t channels = static_cast<std::size_t>(image.channels);
  for (std::size_t pixel = 0; pixel < image.pixelCount(); ++pixel) {
    for (std::size_t c = 0; c < channels; ++c) {
      const float v = image.pixels[pixel * channels + c];
      if (std::isfinite(v)) continue;
      if (found.count == 0) {
        found.firstX = static_cast<int>(pixel % static_cast<std::size_t>(image.width));
        found.firstY = static_cast<int>(pixel / static_cast<std::size_t>(image.width));
        found.firstValue = v;
      }
      ++found.count;
      break;
    }
  }
  return found;
}

void requireFiniteOutput(const FloatImage& image, std::string_view output) {
  NonFinitePixels bad = nonFinitePixels(image);
  if (bad.count == 0) return;
  throw Error(std::string(output) + ": not written: " + std::to_string(bad.count) + " of " +
              std::to_string(image.pixelCount()) + " pixels came out non-finite (the first, (" +
              std::to_string(bad.firstX) + ", " + std::to_string(bad.firstY) + "), holds " +
              (std::isnan(bad.firstValue) ? "nan" : bad.firstValue > 0.0f ? "inf" : "-inf") +
              "); the scene's numbers overflow the float pipeline");
}

}  // namespace prism::imaging

#include "imaging/float_image.h"

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
              "' (known: linear-srgb, xyz, camera-rgb, other-rgb)");
}

FloatImage::FloatImage(int width_, int height_, int channels_, float fill)
    : width(width_), height(height_), channels(channels_) {
  PRISM_CHECK(width >= 0 && height >= 0);
  PRISM_CHECK(channels == 1 || channels == 3 || channels == 4);
  pixels.assign(pixelCount() * static_cast<std::size_t>(channels), fill);
}

}  // namespace prism::imaging

#include "harness/display_png.h"

#include <cmath>

#include "render/display_transform.h"

namespace prism::harness {

imaging::PngImage displayPng(const render::Renderer& renderer) {
  const int width = renderer.settings().width, height = renderer.settings().height;
  std::vector<std::uint8_t> rgba = renderer.readDisplayRgba8();
  imaging::PngImage image(width, height, {});
  image.setColourSpace(renderer.settings().display.colourSpace);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
      image.setPixel(x, y, {rgba[i], rgba[i + 1], rgba[i + 2]});
    }
  }
  return image;
}

imaging::PngImage displayImage(const imaging::FloatImage& tristimulus, const render::DisplaySettings& settings,
                               const Observer& tristimulusObserver, float sceneEv100,
                               const std::optional<Eigen::Matrix3d>& cameraToXyz) {
  render::DisplayInputs inputs = render::resolveDisplay(settings, tristimulusObserver);
  if (cameraToXyz && tristimulusObserver.isCamera) inputs.tristimulusToXyz = *cameraToXyz;
  const render::DisplayTransform transform = render::displayTransform(settings, inputs, sceneEv100);
  imaging::PngImage image(tristimulus.width, tristimulus.height, {});
  image.setColourSpace(settings.colourSpace);
  auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(v * 255.0f)); };
  for (int y = 0; y < tristimulus.height; ++y) {
    for (int x = 0; x < tristimulus.width; ++x) {
      glm::vec3 t(tristimulus.at(x, y, 0), tristimulus.at(x, y, 1), tristimulus.at(x, y, 2));
      glm::vec3 rgb = render::encodeForDisplay(transform, settings.toneMap, t);
      image.setPixel(x, y, {byte(rgb.x), byte(rgb.y), byte(rgb.z)});
    }
  }
  return image;
}

}  // namespace prism::harness

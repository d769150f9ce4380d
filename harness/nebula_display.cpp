#include "harness/nebula_display.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "spectral/colour_space.h"

namespace prism::harness {
namespace {

double whiteLevel(std::vector<double> values) {
  if (values.empty()) return 1.0;
  std::size_t at = std::min(values.size() - 1, static_cast<std::size_t>(0.995 * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
  return values[at] > 0.0 ? values[at] : 1.0;
}

}  // namespace

NebulaWhite nebulaWhiteLevels(const nebula::NebulaImage& image, bool hubble) {
  NebulaWhite white{};
  for (int c = 0; c < 3; ++c) {
    if (!hubble && c != 1) continue;
    std::vector<double> values;
    values.reserve(image.pixels.size());
    for (const auto& p : image.pixels) values.push_back(p[c]);
    white[static_cast<std::size_t>(c)] = whiteLevel(std::move(values));
  }
  if (!hubble) white[0] = white[2] = white[1];
  return white;
}

imaging::FloatImage nebulaDisplayLinear(const nebula::NebulaImage& image, const NebulaWhite& white) {
  imaging::FloatImage linear(image.width, image.height, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      linear.pixels[3 * i + c] = static_cast<float>(image.pixels[i][static_cast<int>(c)] / white[c]);
  return linear;
}

imaging::PngImage nebulaDisplayPng(const nebula::NebulaImage& image, bool hubble) {
  return nebulaDisplayPng(image, hubble, nebulaWhiteLevels(image, hubble));
}

imaging::PngImage nebulaDisplayPng(const nebula::NebulaImage& image, bool hubble, const NebulaWhite& white) {
  const RgbColourSpace& srgb = colourSpace("srgb");
  const imaging::FloatImage linear = nebulaDisplayLinear(image, white);
  imaging::PngImage png(image.width, image.height, {0, 0, 0});
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = 3 * static_cast<std::size_t>(y * image.width + x);
      Eigen::Vector3d v(linear.pixels[i], linear.pixels[i + 1], linear.pixels[i + 2]);
      if (!hubble) v = srgb.xyzToRgb * v;
      Eigen::Vector3d e = srgb.encode(v.cwiseMax(0.0).cwiseMin(1.0));
      auto q = [](double u) { return static_cast<std::uint8_t>(std::lround(std::clamp(u, 0.0, 1.0) * 255.0)); };
      png.setPixel(x, y, {q(e[0]), q(e[1]), q(e[2])});
    }
  return png;
}

}  // namespace prism::harness
